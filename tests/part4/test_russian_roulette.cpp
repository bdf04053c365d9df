// Russian roulette (P4T2): each bounce after the first continues with
// probability p = settings.rr_continue_prob and the survivors are divided by
// p, so the mean is unchanged, E[X'] = p * (X / p) + (1 - p) * 0 = E[X], and
// the variance rises. Tested in the white furnace, where the mean is known in
// closed form (common.h, support/part4_scenes.h).
#include "common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

GRADED_TEST(RussianRoulette, KeepsTheMean, "P4T2", 2, Visible) {
  // at_least_one_bounce_radiance with roulette against the closed form
  // Le (a + ... + a^m). Two-sided t tests, n = 50000, alpha_each(4) each.
  // The estimators are bounded or exponentially tailed: with p = a every
  // path weight a^k / p^(k-1) is at most 1 and the path length is geometric;
  // with (a, p, m) = (0.8, 0.5, 5) the weight is at most 0.8^4 / 0.5^3 = 3.3.
  // Relative standard deviations (closed form) 0.6 at most: standard error
  // below 0.3% of the mean. Power: forgetting to divide by p gives
  // 1.5 (0.5 + 0.25 + 0.083) = 1.25 instead of 1.5 for (0.5, 0.5) (-17%,
  // about 70 standard errors); continuing with probability 1 - p instead of
  // p is off by factors (0.2/0.8)^k for (0.8, 0.8); both are also far off
  // in the other cases.
  struct Case {
    double a, p;
    int m;
  };
  const Case cases[] = {{0.5, 0.5, 1000}, {0.8, 0.8, 1000}, {0.3, 0.3, 1000}, {0.8, 0.5, 5}};
  const double alpha = alpha_each(4);
  uint64_t seed = 4600;
  for (const Case& c : cases) {
    Scene scene = make_white_furnace(c.a, kLe);
    const RenderSettings s = furnace_settings(c.m, c.p);
    stats::RunningStats st = sample(scene, furnace_aim(scene), s, Entry::AtLeastOneBounce, 50000, test::seed(seed++));
    std::ostringstream what;
    what << "at_least_one_bounce_radiance in the furnace, albedo " << c.a << ", " << describe(s);
    EXPECT_TRUE(stats::mean_matches(st, furnace_bounces(c.a, 1, c.m), alpha, what.str()))
        << "Russian roulette must leave the mean unchanged: survivors are divided by p";
  }
}

GRADED_TEST(RussianRoulette, RaisesTheVariance, "P4T2", 2, Hidden) {
  // Furnace a = 0.8, max_ray_depth 6: per-estimate variance with p = 0.5
  // against p = 1 (no roulette), 40000 estimates each. Closed form (the
  // recursion T_j = D_j + c_j T_(j+1), E[c^2] = a^2 / p after the first
  // bounce): the ratio is 13.8; it would still be 5.2 if roulette only began
  // one bounce later. One-sided log-variance-ratio test (statistics.h,
  // valid for these skewed samples) of H0 "ratio >= 2" at alpha = 1e-5: a
  // correct solution (ratio >= 5) fails with probability below 1e-5. With
  // n = 40000 the standard error of the log ratio is about 0.03, so a
  // solution without roulette (ratio 1, log 2 = 0.69 below the bound) fails
  // with certainty.
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
