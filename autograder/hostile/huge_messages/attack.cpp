// Hostile: failure messages as large as a test can make them. Every stub task
// throws 60,000 bytes of quotes, backslashes, control characters and broken
// UTF-8 (each costs 2 to 6 bytes in JSON) where it would throw "not
// implemented", so every test of the part fails with it: about 150 KB of JSON
// per test, 7 MB for the part. (The worker's link carries an exception's text
// up to 64 KiB; more breaks the link, which costs the test as well.)
#include <stdexcept>
#include <string>

#include "core/not_implemented.h"

namespace {
[[noreturn]] void throw_huge(const char* task) {
  std::string text = std::string("not implemented: ") + task + " ";
  while (text.size() < 60000) text += "\"\\\x01\x1b[31m\xff";
  throw std::runtime_error(text);
}
}  // namespace
#define NotImplemented(task) (throw_huge(task), NotImplemented(task))
