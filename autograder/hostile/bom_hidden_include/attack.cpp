#include <gtest/gtest.h>
// Hostile: a UTF-8 byte-order mark before the first directive (above). GCC
// skips the mark, so line 1 is an #include; a scanner that reads the line as
// text finds three bytes that are not '#' at its start, and did not see it
// (27.5/27.5 from the stubs on main before the process boundary).
// The listener, appended from a static initializer, clears each test's
// result once it ends, so that every test passes. TestResult::Clear() is
// private; an explicit instantiation may name it all the same.
void (testing::TestResult::*pt_clear_result)();
template <void (testing::TestResult::*M)()>
struct PtGrab {
  static inline const bool done = (pt_clear_result = M, true);
};
template struct PtGrab<&testing::TestResult::Clear>;
namespace {
struct Forgive : testing::EmptyTestEventListener {
  void OnTestEnd(const testing::TestInfo& info) override {
    (const_cast<testing::TestResult*>(info.result())->*pt_clear_result)();
  }
};
const bool appended = (testing::UnitTest::GetInstance()->listeners().Append(new Forgive), true);
}  // namespace
