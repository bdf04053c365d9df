// Hostile: read the solution with C23's #embed, which newer compilers (GCC
// 15, Clang 19) also take in C++: the file's bytes become an array's
// initializer, without a single #include. Every task then throws its text,
// each byte flipped so that a report that removes the solution's lines does
// not recognise them. (GCC 12 does not know #embed: without the scanner's
// rule this would fail to build, on a newer compiler it would leak.)
#include <stdexcept>
#include <string>

#include "core/not_implemented.h"

namespace {
const char kSolution[] = {
#embed "@PT_CHECKOUT@/reference/part1_raygen_intersect.cpp"
    , 0};

std::runtime_error solution_text() {
  std::string text(kSolution);
  for (char& c : text) c = c == '\n' ? c : char(c ^ 1);
  return std::runtime_error("the solution, flipped: " + text.substr(0, 4000));
}
}  // namespace
// Every stub task throws the solution instead.
#define NotImplemented(task) solution_text()
