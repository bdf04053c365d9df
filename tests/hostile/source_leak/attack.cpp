// Hostile: read the solution. PT_SOURCE_DIR (a compile definition every task
// file sees) gives the grader's source tree; every task throws the text of the
// reference file of this part, so it appears in the failure message of each
// visible test, which the student is shown.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/not_implemented.h"

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
