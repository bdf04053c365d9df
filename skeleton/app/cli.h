#pragma once

namespace pt {

// The `pathtracer` command line. Returns the exit status.
// `student_parts`: the parts this binary took from tasks/ (e.g. "1,2"; "" for
// none, the course's solution stands in for the others), said at the start of
// every render so that nobody mistakes the solution's image for their own;
// nullptr when the build did not say. `chosen_by`: how the build chose them,
// "auto" or "PT_REFERENCE_PARTS" (app/part_origins.h).
int run_cli(int argc, char** argv, const char* student_parts = nullptr, const char* chosen_by = nullptr);

}  // namespace pt
