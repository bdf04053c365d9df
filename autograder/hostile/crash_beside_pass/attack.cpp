// Hostile (or broken): a part whose binary dies before its test main, every
// time. A static initializer writes through a null pointer. The submission's
// part 5 is the solution: the crash of part 1 must cost part 1 only.
namespace {
int write_through_null() {
  volatile int* volatile p = nullptr;  // both volatile, or the compiler drops the store
  *p = 1;
  return 0;
}
const int crashed = write_through_null();
}  // namespace
