// Hostile: read the solution. The attack knows where the grader's source tree
// is (PT_SOURCE_DIR, when a build defines it; otherwise a guess of the
// instructor's checkout, as a student who has seen the course's layout or
// Gradescope's /autograder/source would: the gallery writes the real path in
// for the placeholder below, the worst case). Every task throws the text of
// the reference file of this part, so it would appear in the failure message
// of each visible test, which the student is shown.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/not_implemented.h"

#ifndef PT_SOURCE_DIR
#define PT_SOURCE_DIR "@PT_CHECKOUT@"
#endif

namespace {
std::runtime_error solution_text() {
  const std::string path = std::string(PT_SOURCE_DIR) + "/reference/part1_raygen_intersect.cpp";
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return std::runtime_error(in ? path + ":\n" + text.str() : "could not read " + path);
}
}  // namespace
// Every stub task throws the solution instead.
#define NotImplemented(task) solution_text()
