// Hostile: vanish. exit(0) in a static initializer: nothing is listed and
// nothing runs, so a grader that trusts the binary's own list drops the part
// from the table and its maximum from the total.
#include <cstdlib>

namespace {
const int vanished = (std::exit(0), 0);
}  // namespace
