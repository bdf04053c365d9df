// Hostile (or just broken): a destructor that throws while another exception
// is in flight, which ends the program through std::terminate. Only the tests
// of P1T3 may lose points.
#include <stdexcept>

namespace {
struct ThrowsOnDestruction {
  ~ThrowsOnDestruction() noexcept(false) { throw std::runtime_error("from a destructor"); }
};
void throw_twice() {
  ThrowsOnDestruction guard;
  throw std::runtime_error("first");
}
}  // namespace
