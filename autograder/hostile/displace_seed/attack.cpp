// Hostile: choose the seeds. Every statistical test draws from
// pt::test::seed(base); defining it (and its setter) here used to displace the
// test support's own definition, so a submission could pick the one seed under
// which its biased estimator happens to pass.
#include <cstdint>
#include <cstdio>

namespace pt::test {
void set_seed_offset(uint64_t) {}
uint64_t seed(uint64_t) {
  std::fputs("[displace_seed] the submission chose this seed\n", stderr);
  return 42;
}
}  // namespace pt::test
