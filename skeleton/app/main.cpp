#include "app/cli.h"

// PT_STUDENT_PARTS: the parts this binary links from tasks/, set by the build
// (the top-level CMakeLists: all but PT_REFERENCE_PARTS).
#ifdef PT_STUDENT_PARTS
int main(int argc, char** argv) { return pt::run_cli(argc, argv, PT_STUDENT_PARTS); }
#else
int main(int argc, char** argv) { return pt::run_cli(argc, argv); }
#endif
