// Hostile: GoogleTest's registry reached without its header. The include
// allowlist stops <gtest/gtest.h>, not a declaration written out by hand: a
// static initializer asks testing::UnitTest for its instance, the first step
// of appending a listener that clears each test's result (the full listener
// is in bom_hidden_include). pt-link-guard refuses a task file that uses what
// only the tests, their support or GoogleTest define.
namespace testing {
class UnitTest {
 public:
  static UnitTest* GetInstance();
};
}  // namespace testing
namespace {
testing::UnitTest* const pt_registry = testing::UnitTest::GetInstance();
}
