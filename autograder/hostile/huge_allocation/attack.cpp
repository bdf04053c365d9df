// Hostile (or just broken): a 50 GB allocation in one task, zero-filled so that
// every page would be touched. Only the tests of P1T4 may lose points, and the
// grading machine must not run out of memory.
#include <vector>

namespace {
char fifty_gigabytes() {
  std::vector<char> block(50'000'000'000ull);
  return block[block.size() / 2];
}
}  // namespace
