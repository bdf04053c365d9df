// Hostile: replace a piece of GoogleTest. GoogleTest runs each test body
// through a function template whose copy in libgtest is a weak (inline)
// definition; an explicit specialization here is a strong one, which the
// linker prefers without a word. This one swallows every exception, so a test
// whose task throws "not implemented" passes.
// No header: <gtest/gtest.h> is not allowed in the grading kit, and none is
// needed. The template's declaration is written out, and a pointer to a
// member of the incomplete class testing::Test can still be called.
namespace testing {
class Test;
namespace internal {
template <class T, typename Result>
Result HandleExceptionsInMethodIfSupported(T* object, Result (T::*method)(), const char* location);

template <>
void HandleExceptionsInMethodIfSupported<Test, void>(Test* object, void (Test::*method)(), const char*) {
  try {
    (object->*method)();
  } catch (...) {
  }
}
}  // namespace internal
}  // namespace testing
