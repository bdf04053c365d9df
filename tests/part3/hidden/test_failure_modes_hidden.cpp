// Hidden P3T3 and P3T4 tests: self-shadowing of sampled rays, and variances
// falling as 1/N. Variance checks: the one-sided log-variance-ratio test of
// support/statistics.h at alpha = 1e-5 (see test_failure_modes.cpp).
#include "../common.h"
#include "../grazing_plane.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

GRADED_TEST(HemisphereLighting, NoSelfShadowingAtGrazingAngles, "P3T3", 1, Hidden) {
  // Under a uniform sky every hemisphere sample that escapes brings the sky's
  // radiance (cos theta > 0 but for a 2^-32 chance): an exactly zero estimate
  // (ns_area_light = 1, one sample) means the ray hit its own surface.
  GrazingPlane g;
  const Frame f = Frame::from_normal(g.n);
  g.scene.add_light<SkyLight>(Spectrum(1.0));
  g.scene.add_quad(g.centre, f.s * 40.0, f.t * 40.0, g.scene.add_bsdf<DiffuseBSDF>(Spectrum(kAlbedo)));
  g.scene.build();
  PathTracer tracer(g.scene, settings_with(1));
  const int zeros = count_zero_estimates(g, kGrazingPoints, test::seed(3520), [&](const Ray& r, const Intersection& i,
                                                                                  Rng& rng) {
    return tracer.estimate_direct_lighting_hemisphere(r, i, rng);
  });
  EXPECT_LE(zeros, kMaxFalselyShadowed) << "of " << kGrazingPoints
                                        << " sky-lit points saw their own surface: offset the sampled rays "
                                           "(min_t = kRayEpsilon)";
}

// ---- Variance -----------------------------------------------------------------------

// Var(one estimate with ns_area_light = 1) / Var(one with ns = 16) is 16 for
// an average of independent samples (more if a solution stratifies its
// hemisphere samples, which is allowed: H0 is "ratio >= 16"). Sample counts:
// 1e5 estimates at ns = 1, 2e4 at ns = 16: se of the log ratio about 0.03
// (hemisphere, kurtosis ~4) against log 16 = 2.8: an estimator that ignores
// ns_area_light, or adds the samples up instead of averaging, fails.
void check_one_over_n(Method m, uint64_t seed) {
  Lit lit = moderate_light();
  stats::RunningStats one = run(lit, m, settings_with(1), 100000, test::seed(seed));
  stats::RunningStats sixteen = run(lit, m, settings_with(16), 20000, test::seed(seed + 1));
  EXPECT_TRUE(stats::check(stats::variance_ratio_at_least(one, sixteen, 16.0, kAlphaTest,
                                                          std::string(name(m)) + ": Var(ns=1) / Var(ns=16)")));
}

GRADED_TEST(HemisphereLighting, VarianceFallsAsOneOverN, "P3T3", 1, Hidden) { check_one_over_n(Method::Hemisphere, 3550); }

GRADED_TEST(LightSampling, VarianceFallsAsOneOverN, "P3T4", 1, Hidden) { check_one_over_n(Method::Importance, 3560); }

}  // namespace
}  // namespace pt
