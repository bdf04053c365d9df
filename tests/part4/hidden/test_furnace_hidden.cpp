// Hidden P4T3 test: est_radiance_global_illumination in the white furnace,
// every depth limit accumulated and isolated (thresholds: test_furnace.cpp).
#include "../common.h"
#include "../furnace_check.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

GRADED_TEST(Furnace, DepthLimitsAndBounceIsolation, "P4T3", 2, Hidden) {
  // est_radiance_global_illumination, p = 1: with accumulate_bounces,
  // Le (1 + ... + a^m); without, bounce m alone, Le a^m, where bounce 0 is
  // the emission seen directly (exactly Le, no noise) and is the only thing
  // kept for m = 0 in both modes. Power (99%): a bias of 0.4% to 1.9%.
  const int depths[] = {0, 1, 2, 3};
  const double albedos[] = {0.3, 0.8};
  const double alpha = alpha_each(2 * 4 * 2);
  uint64_t seed = 4300;
  for (double a : albedos)
    for (int m : depths) {
      EXPECT_TRUE(furnace_check(a, furnace_settings(m, 1.0, true), Entry::GlobalIllumination,
                                furnace_bounces(a, 0, m), alpha, test::seed(seed++)))
          << "accumulate_bounces on: expected Le (1 + a + ... + a^m)";
      EXPECT_TRUE(furnace_check(a, furnace_settings(m, 1.0, false), Entry::GlobalIllumination,
                                furnace_bounces(a, m, m), alpha, test::seed(seed++)))
          << "accumulate_bounces off: expected Le a^m (bounce m alone; for m = 0 the emission seen directly)";
    }
}

}  // namespace
}  // namespace pt
