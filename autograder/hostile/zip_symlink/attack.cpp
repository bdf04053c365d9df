// Hostile: a task file that is a symbolic link. The zip's
// tasks/part1_raygen_intersect.cpp entry is a link to the solution in the
// grader's checkout: a grader that followed it would build the solution as the
// student's.
