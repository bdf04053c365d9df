// Hostile: a task file whose object is 480 MiB of zeros in a data section, so
// that the object and the test binary that links it, each under the build's
// limit on one file (512 MiB), fill the grader's disk together. Graded without
// the tmpfs that bounds the submission's folder (--sandbox-without
// namespaces): what stops it is the grader's check of the folder's size.
asm(".pushsection .data.pt_fill,\"aw\"\n"
    ".zero 0x1E000000\n"
    ".popsection");
