// Hostile: a fork bomb in one task. Every process forks for ever; the grading
// machine must survive it and only the tests of P1T4 may lose points.
#include <unistd.h>

namespace {
void fork_forever() {
  for (;;) ::fork();
}
}  // namespace
