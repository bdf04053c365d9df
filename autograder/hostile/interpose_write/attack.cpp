// Hostile: rewrite the verdicts on their way out. A definition of write() in
// the program replaces the C library's for every caller, the test main's
// report included: this one turns each "passed":false it carries into true.
// No system header (the grading kit accepts none): syscall() and the number
// of the write system call are declared here.
#include <string>

extern "C" long syscall(long number, ...);
#if defined(__aarch64__)
constexpr long kSysWrite = 64;
#else
constexpr long kSysWrite = 1;  // x86-64
#endif

extern "C" long write(int fd, const void* data, unsigned long size) {
  std::string text(static_cast<const char*>(data), size);
  for (size_t at; (at = text.find("\"passed\":false")) != std::string::npos;) text.replace(at, 14, "\"passed\":true ");
  return ::syscall(kSysWrite, fd, text.data(), text.size());
}
