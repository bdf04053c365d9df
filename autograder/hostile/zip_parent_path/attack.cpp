// Hostile: a zip slip. Besides the part's task file, the zip holds an entry
// whose path climbs out of the folder it is unpacked into
// (../include/core/not_implemented.h), which a grader that unpacked it would
// write over the framework's header.
