// The white furnace (P4T1, P4T3): a closed box whose walls all reflect with
// albedo a and emit Le. Bounce k alone carries exactly Le a^k, so
//   max_ray_depth = m, accumulate:      Le (1 + a + ... + a^m)   (-> Le / (1 - a))
//   max_ray_depth = m, bounce m alone:  Le a^m
// and at_least_one_bounce_radiance (no zero bounce) gives the same without
// the leading Le. See support/part4_scenes.h for why hemisphere sampling.
//
// Thresholds. Each check is a two-sided t test of the mean of n = 50000
// estimates against the closed form at level alpha_each(checks) (Šidák share
// of kAlphaTest = 1e-5 per test). The estimators are bounded (p = 1 or
// p >= a: every path weight is at most 1, each vertex adds at most 2 a Le),
// so the t statistic is normal to far in the tail. Relative standard
// deviations are 0.13 to 0.26 (closed form: each vertex's direct light is
// 2 a Le U with U uniform on [0, 1], and the recursion of
// test_russian_roulette.cpp gives the variance of the sum), so the standard
// error is below 0.12% of the mean and a check at alpha ~ 1e-6 (|t| ~ 5)
// resolves biases of 0.6%. Power against the mutants of
// the mutant gallery's part 4 (instructors' copies): one level too deep multiplies the depth-1 value
// of at_least_one_bounce_radiance by 1 + a (+30% or more); emission at every
// vertex, a missing cos (weight 2a on average) or a pdf divided twice (weight
// a pi / cos) change every value with a bounce by more than 30%; keeping the
// first bounce instead of the last multiplies Le a^m by a^(1-m) >= 1.25 for
// m >= 2. Each is more than 100 standard errors.
#include "common.h"
#include "furnace_check.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

const double kAlbedos[] = {0.3, 0.5, 0.8};

// ---- P4T1: at_least_one_bounce_radiance --------------------------------------

GRADED_TEST(Furnace, EachDepthLimit, "P4T1", 3, Visible) {
  // at_least_one_bounce_radiance with r.depth = max_ray_depth = m returns
  // bounces 1..m: Le (a + ... + a^m). Russian roulette off (p = 1), so that
  // only the recursion and its depth are tested here. Power (99%): a bias of
  // 0.9% (the best-resolved configuration) to 1.9% (every configuration).
  const int depths[] = {1, 2, 3, 5};
  const double alpha = alpha_each(3 * 4);
  uint64_t seed = 4000;
  for (double a : kAlbedos)
    for (int m : depths)
      EXPECT_TRUE(furnace_check(a, furnace_settings(m, 1.0), Entry::AtLeastOneBounce, furnace_bounces(a, 1, m), alpha,
                                test::seed(seed++)))
          << "expected Le (a + ... + a^m): the direct light at each of the m vertices, each bounce weighted by "
             "f cos / pdf = a";
}

GRADED_TEST(Furnace, KeepsOnlyTheLastBounce, "P4T1", 2, Visible) {
  // accumulate_bounces off: at_least_one_bounce_radiance keeps only the
  // direct light of the last vertex (r.depth == 1), bounce m: Le a^m.
  // Power (99%): a bias of 1.9% in any configuration.
  const int depths[] = {1, 2, 3, 4};
  const double alpha = alpha_each(3 * 4);
  uint64_t seed = 4100;
  for (double a : kAlbedos)
    for (int m : depths)
      EXPECT_TRUE(furnace_check(a, furnace_settings(m, 1.0, /*accumulate=*/false), Entry::AtLeastOneBounce,
                                furnace_bounces(a, m, m), alpha, test::seed(seed++)))
          << "expected Le a^m: only bounce m = max_ray_depth, the direct light of the last vertex, carried by the "
             "m - 1 bounce weights before it";
}

// ---- P4T3: est_radiance_global_illumination -----------------------------------

GRADED_TEST(Furnace, FullEstimate, "P4T3", 3, Visible) {
  // Large depth (1000) with Russian roulette: Le (1 - a^1001) / (1 - a),
  // i.e. Le / (1 - a) to 1e-52. p = 0.7 (the default) for a = 0.3 and 0.5,
  // p = 0.9 for a = 0.8 (p >= a keeps every path weight a^k / p^(k-1) <= 1;
  // with p < a^2 the variance would grow without bound with the depth).
  // Power (99%): a bias of 0.4% (a = 0.3) to 1.1% (a = 0.8).
  struct Case {
    double a, p;
  };
  const Case cases[] = {{0.3, 0.7}, {0.5, 0.7}, {0.8, 0.9}};
  const double alpha = alpha_each(3);
  uint64_t seed = 4200;
  for (const Case& c : cases)
    EXPECT_TRUE(furnace_check(c.a, furnace_settings(1000, c.p), Entry::GlobalIllumination,
                              furnace_bounces(c.a, 0, 1000), alpha, test::seed(seed++)))
        << "expected Le / (1 - a): the emission seen directly plus every bounce";
}

}  // namespace
}  // namespace pt
