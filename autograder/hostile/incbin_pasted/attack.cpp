// Hostile: read the solution while the submission is built, past the intake's
// search. The assembler's directive that copies a file into the program
// copies any file the compiler can read; here its name is pasted together by
// the preprocessor, so that the word appears nowhere in the file. Every task then
// throws the file's text, each byte flipped so that a report that removes the
// solution's lines does not recognise them.
#include <stdexcept>
#include <string>

#include "core/not_implemented.h"

#define PASTE(a, b) a##b
#define TEXT(x) #x
#define STRING(x) TEXT(x)
asm(".section .rodata\n.globl pt_solution\npt_solution:\n" STRING(.PASTE(inc, bin))
    " \"@PT_CHECKOUT@/reference/part1_raygen_intersect.cpp\"\n.byte 0\n.previous");
extern "C" const char pt_solution[];

namespace {
std::runtime_error solution_text() {
  std::string text(pt_solution);
  for (char& c : text) c = c == '\n' ? c : char(c ^ 1);
  return std::runtime_error("the solution, flipped: " + text.substr(0, 4000));
}
}  // namespace
// Every stub task throws the solution instead.
#define NotImplemented(task) solution_text()
