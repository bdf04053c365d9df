// Hostile (or a forgotten debug print): 256 MiB on stdout from one task, once
// per process. The grader's disk must not fill up, and correct work must keep
// its points.
#include <cstdio>
#include <string>

namespace {
void flood_once() {
  static bool flooded = false;
  if (flooded) return;
  flooded = true;
  const std::string line(1023, 'x');
  for (int i = 0; i < 256 * 1024; ++i) std::printf("%s\n", line.c_str());
}
}  // namespace
