// Hostile (or just broken): unbounded recursion in one task. The Moller-Trumbore
// test behind both Triangle functions recurses until the stack runs out; only
// the tests of P1T3 may lose points.
namespace {
int recurse_forever(int depth) {
  volatile char frame[512];
  frame[0] = static_cast<char>(depth);
  return recurse_forever(depth + 1) + frame[0];  // not a tail call
}
}  // namespace
