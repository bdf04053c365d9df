// Not an attack on its own: the grader is killed (an outer timeout, a lost
// machine) while this submission's tests hang. The report on disk must still
// list every test of the part at its full points, none graded, and nothing of
// the run may outlive the grader.
#include "core/not_implemented.h"

namespace {
[[noreturn]] void hang() {
  for (volatile bool forever = true; forever;) {
  }
  __builtin_unreachable();
}
}  // namespace
// Every stub task hangs where it would throw.
#define NotImplemented(task) (hang(), NotImplemented(task))
