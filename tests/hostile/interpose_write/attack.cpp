// Hostile: rewrite the verdicts on their way out. A definition of write() in
// the program replaces the C library's for every caller, the test main's
// report included: this one turns each "passed":false it carries into true.
#include <sys/syscall.h>
#include <unistd.h>

#include <string>

extern "C" ssize_t write(int fd, const void* data, size_t size) {
  std::string text(static_cast<const char*>(data), size);
  for (size_t at; (at = text.find("\"passed\":false")) != std::string::npos;) text.replace(at, 14, "\"passed\":true ");
  return ::syscall(SYS_write, fd, text.data(), text.size());
}
