// Hostile (or just broken): a SIGSEGV in one task. Sphere::test writes
// through a null pointer; the other tasks are the reference's, so only the
// tests of P1T4 may lose points.
namespace {
void write_through_null() {
  volatile int* volatile p = nullptr;  // both volatile, or the compiler drops the store
  *p = 1;
}
}  // namespace
