// Hostile (or careless): a task file over the grader's 1 MiB limit, here the
// stubs padded with comment lines past 1.1 MB. Reading, scanning and
// compiling such files would cost the grader without bound; the limit stops
// it before anything is read past 1 MiB.
