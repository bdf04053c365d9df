// Hostile: run before the test main. A function in .preinit_array runs before
// every static initializer; if it ran before the test main's own, it could
// read the grading channel's key from the inherited descriptor and forge
// verdicts with it. It tries every descriptor from 3 to 63.
#include <cstdio>

// No system header (the grading kit accepts none): the POSIX call declared here.
extern "C" long read(int fd, void* data, unsigned long size);

namespace {
void steal(int, char**, char**) {
  char buf[256];
  for (int fd = 3; fd < 64; ++fd)
    if (const auto n = ::read(fd, buf, sizeof buf); n > 0)
      std::fprintf(stderr, "[preinit_steal] read %zd bytes from descriptor %d\n", n, fd);
}
__attribute__((section(".preinit_array"), used)) void (*const run_first)(int, char**, char**) = steal;
}  // namespace
