#pragma once

namespace pt {

// The `pathtracer` command line. Returns the exit status.
// `student_parts`: the parts this binary took from tasks/ (e.g. "1,2"; "" for
// none, the course's solution stands in for the others), said at the start of
// every render so that nobody mistakes the solution's image for their own;
// nullptr when the build did not say.
int run_cli(int argc, char** argv, const char* student_parts = nullptr);

}  // namespace pt
