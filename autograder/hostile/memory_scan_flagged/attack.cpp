// Not scored as an attack, flagged for the instructor: the ways a task file
// reads its own process's memory without naming anything in it. The linker's
// boundary symbols (__bss_start, _end) give the program's data to scan with
// memmem (the grading key lives somewhere in it from the first task call on),
// an integer made a pointer reads a fixed address, "/proc/self/maps" lists
// every mapping, and ## builds a grader's name the scanner cannot read. None
// of it runs here (the task functions are the solution's): the score must be
// full, and the source flags must name each.
#include <cstddef>
#include <cstring>
extern "C" char __bss_start[], _end[];
#define PT_CAT(a, b) a##b
namespace {
int PT_CAT(gra, ding_calls) = 0;
}  // namespace
const char* pt_scan_own_memory(const char* needle, size_t n) {
  const char* maps = "/proc/self/maps";
  const char* fixed = (const char*)0x400000;
  if (n == 0) return maps + (fixed == nullptr) + grading_calls;
  return static_cast<const char*>(memmem(__bss_start, static_cast<size_t>(_end - __bss_start), needle, n));
}
