#include "app/cli.h"

// PT_CHOSEN_PARTS: the build chose each part's side (the top-level
// CMakeLists, PT_REFERENCE_PARTS) and says which in one header per part.
// PT_STUDENT_PARTS alone: the parts this binary links from tasks/.
#ifdef PT_CHOSEN_PARTS
#include "part1_chosen.h"
#include "part2_chosen.h"
#include "part3_chosen.h"
#include "part4_chosen.h"
#include "part5_chosen.h"
#define PT_STUDENT_PARTS \
  PT_PART1_FROM_TASKS PT_PART2_FROM_TASKS PT_PART3_FROM_TASKS PT_PART4_FROM_TASKS PT_PART5_FROM_TASKS
#endif

#if defined(PT_STUDENT_PARTS) && defined(PT_PARTS_CHOSEN_BY)
int main(int argc, char** argv) { return pt::run_cli(argc, argv, PT_STUDENT_PARTS, PT_PARTS_CHOSEN_BY); }
#elif defined(PT_STUDENT_PARTS)
int main(int argc, char** argv) { return pt::run_cli(argc, argv, PT_STUDENT_PARTS); }
#else
int main(int argc, char** argv) { return pt::run_cli(argc, argv); }
#endif
