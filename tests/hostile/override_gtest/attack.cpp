// Hostile: replace a piece of GoogleTest. GoogleTest runs each test body
// through a function template whose copy in libgtest is a weak (inline)
// definition; an explicit specialization here is a strong one, which the
// linker prefers without a word. This one swallows every exception, so a test
// whose task throws "not implemented" passes.
#include <gtest/gtest.h>

namespace testing::internal {
template <class T, typename Result>
Result HandleExceptionsInMethodIfSupported(T* object, Result (T::*method)(), const char* location);

template <>
void HandleExceptionsInMethodIfSupported<Test, void>(Test* object, void (Test::*method)(), const char*) {
  try {
    (object->*method)();
  } catch (...) {
  }
}
}  // namespace testing::internal
