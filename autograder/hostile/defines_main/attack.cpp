// Hostile: a main() of its own. A program has one main; if the task file's
// were linked in place of the test main's, it would decide what the binary
// reports (here, that it ran and every test passed) and GoogleTest would
// never run. The stubs follow, untouched.
#include <cstdio>

int main() {
  std::puts("[  PASSED  ] every graded test");
  return 0;
}
