// Hostile: a fork bomb in one task. Every process forks for ever; the grading
// machine must survive it and only the tests of P1T4 may lose points.
// No system header (the grading kit accepts none): fork() declared here.
extern "C" int fork();

namespace {
void fork_forever() {
  for (;;) ::fork();
}
}  // namespace
