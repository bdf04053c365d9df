#pragma once
// Where this build of pt-grade was made (what CMake knows): compiled into one
// small file (build_paths.cpp) so that every other file of pt-grade compiles
// to the same command in any tree, and a compiler cache serves the release's
// and the Gradescope kit's builds of it from the instructor's.
namespace pt::grade::build_paths {

const char* default_kit();     // the grading kit `pt-grade submission` uses unless told
const char* grade_readable();  // what graded code may read besides the system: the scenes
const char* source_root();     // the tree: check-submission compares it with the release's record
const char* binary_root();     // its build folder: check-submission builds there

}  // namespace pt::grade::build_paths
