#pragma once
// The two checks ctest runs on every build: the untouched stubs fail every
// graded test naming the task, and each mutant fails at least one.
#include "run/grade_part.h"

namespace pt::grade {

// Print what is wrong; return 0 when the check passes, 1 when it fails.
int check_stubs(const PartResult& result);
int check_mutant(const PartResult& result);

}  // namespace pt::grade
