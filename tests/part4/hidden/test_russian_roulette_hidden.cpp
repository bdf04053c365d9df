// Hidden P4T2 tests: Russian roulette raises the variance, and paths at a
// high albedo end by roulette without overflow or NaN.
#include "../common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

GRADED_TEST(RussianRoulette, RaisesTheVariance, "P4T2", 2, Hidden) {
  // Furnace a = 0.8, max_ray_depth 6: per-estimate variance with p = 0.5
  // against p = 1 (no roulette), 40000 estimates each. Closed form (the
  // recursion T_j = D_j + c_j T_(j+1), E[c^2] = a^2 / p after the first
  // bounce): the ratio is 13.8; it would still be 5.2 if roulette only began
  // one bounce later. One-sided log-variance-ratio test (statistics.h,
  // valid for these skewed samples) of H0 "ratio >= 2" at alpha = 1e-5: a
  // correct solution (ratio >= 5) fails with probability below 1e-5. With
  // n = 40000 the standard error of the log ratio is 0.016, so a solution
  // without roulette (ratio 1, log 2 = 0.69 below the bound) fails with
  // certainty. Power (99%): a true ratio of 1.8 or less fails.
  Scene scene = make_white_furnace(0.8, kLe);
  const Aim target = furnace_aim(scene);
  const RenderSettings with_rr = furnace_settings(6, 0.5), without_rr = furnace_settings(6, 1.0);
  stats::RunningStats a = sample(scene, target, with_rr, Entry::AtLeastOneBounce, 40000, test::seed(4700));
  stats::RunningStats b = sample(scene, target, without_rr, Entry::AtLeastOneBounce, 40000, test::seed(4701));
  EXPECT_TRUE(stats::check(stats::variance_ratio_at_least(
      a, b, 2.0, kAlphaTest,
      "Var(rr_continue_prob = 0.5) / Var(rr_continue_prob = 1), furnace a = 0.8, max_ray_depth 6")))
      << "Russian roulette trades variance for speed: with p = 0.5 some paths must stop early";
}

GRADED_TEST(RussianRoulette, HighAlbedoIsStable, "P4T2", 1, Hidden) {
  // a = 0.95, max_ray_depth 10000: paths end by roulette, not by depth
  // (expected length 1 + 1 / (1 - p) vertices); no stack overflow, no NaN.
  // (1) p = 0.95: bounded weights (a^k / p^(k-1) = a), mean
  // Le a (1 - a^10000) / (1 - a) = 19 Le; t test, n = 20000, relative
  // standard error 0.7%. (2) p = 0.7 (the default): every estimate finite
  // and non-negative (p < a^2 makes the variance enormous, so no mean test).
  // Power of (1) (99%): a bias of 4.4%.
  Scene scene = make_white_furnace(0.95, kLe);
  const Aim target = furnace_aim(scene);
  const RenderSettings s = furnace_settings(10000, 0.95);
  stats::RunningStats st = sample(scene, target, s, Entry::AtLeastOneBounce, 20000, test::seed(4800));
  EXPECT_TRUE(stats::mean_matches(st, furnace_bounces(0.95, 1, 10000), kAlphaTest, "furnace a = 0.95, " + describe(s)));

  PathTracer tracer(scene, furnace_settings(10000, 0.7));
  Rng rng(test::seed(4801));
  int bad = 0;
  for (int i = 0; i < 5000; ++i) {
    const Spectrum L = estimate_once(tracer, target, Entry::AtLeastOneBounce, rng);
    bad += !is_finite(L) || L.r < 0.0 || L.g < 0.0 || L.b < 0.0;
  }
  EXPECT_EQ(bad, 0) << "estimates (of 5000) that were NaN, infinite or negative: furnace a = 0.95, max_ray_depth "
                       "10000, rr_continue_prob 0.7";
}

}  // namespace
}  // namespace pt
