// Hostile: hide the #include of the solution from a reader and from a
// scanner that looks for quoted paths: the header name comes from a macro
// (the preprocessor expands it; the path is the grader's checkout).
#define SOLUTION "@PT_CHECKOUT@/reference/part1_raygen_intersect.cpp"
#include SOLUTION
