// Hostile: a task file whose object is 1 GiB of zeros in a data section (an
// initialised array does the same), so that the build fills the grader's disk:
// 1 GiB for the object, as much again for the test binary that links it.
asm(".pushsection .data.pt_fill,\"aw\"\n"
    ".zero 0x40000000\n"
    ".popsection");
