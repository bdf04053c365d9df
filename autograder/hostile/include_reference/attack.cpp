// Hostile: hand in the solution. The task file is nothing but an #include of
// the instructor's own: relative, as it worked when task files were compiled
// in the instructor's tree (full marks), and absolute, for the grader's
// checkout (the worst case: a student who knows where it is).
#include "../reference/part1_raygen_intersect.cpp"
#include "@PT_CHECKOUT@/reference/part1_raygen_intersect.cpp"
