// Hidden P3T3 and P3T4 tests: self-shadowing of sampled rays, and variances
// falling as 1/N. Variance checks: the one-sided log-variance-ratio test of
// support/statistics.h at alpha = 1e-5 (see test_failure_modes.cpp).
#include "../common.h"
#include "../grazing_plane.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

// Boundary: more than 20 falsely shadowed points of 20000 (test_failure_modes.cpp).
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
    return estimate(tracer, r, i, Method::Hemisphere, rng);
  });
  EXPECT_LE(zeros, kMaxFalselyShadowed) << "of " << kGrazingPoints
                                        << " sky-lit points saw their own surface: offset the sampled rays "
                                           "(min_t = kRayEpsilon)";
}

// ---- Variance -----------------------------------------------------------------------

// Var(one estimate with ns_area_light = 1) / Var(one with ns = 16) is 16 for
// an average of independent samples (more if a solution stratifies its
// hemisphere samples, which is allowed: H0 is "ratio >= 16"). Sample counts:
// 1e5 estimates at ns = 1, 2e4 at ns = 16: se of the log ratio 0.016
// (hemisphere, kurtosis 13 and 3.7) and 0.011 (light sampling) against
// log 16 = 2.8: an estimator that ignores ns_area_light, or adds the samples
// up instead of averaging, fails. Power (99%): a true ratio of 14.4
// (hemisphere) or 14.9 (light sampling) or less fails.
void check_one_over_n(Method m, uint64_t seed) {
  Lit lit = moderate_light();
  stats::RunningStats one = run(lit, m, settings_with(1), 100000, test::seed(seed));
  stats::RunningStats sixteen = run(lit, m, settings_with(16), 20000, test::seed(seed + 1));
  EXPECT_TRUE(stats::check(stats::variance_ratio_at_least(one, sixteen, 16.0, kAlphaTest,
                                                          std::string(name(m)) + ": Var(ns=1) / Var(ns=16)")));
}

GRADED_TEST(HemisphereLighting, VarianceFallsAsOneOverN, "P3T3", 1, Hidden) { check_one_over_n(Method::Hemisphere, 3550); }

GRADED_TEST(LightSampling, VarianceFallsAsOneOverN, "P3T4", 1, Hidden) { check_one_over_n(Method::Importance, 3560); }

// Section 5: hemisphere sampling takes N = lights x ns_area_light samples, so
// a scene with more lights gets more of them even where the extra lights
// are invisible to it. The 0.8 x 0.6 light alone (N = 1 at ns_area_light = 1)
// against the same light with a point and a directional light added (N = 3;
// hemisphere sampling cannot see delta lights, so each sample has the same
// distribution): Var(one light) / Var(three lights) is 3 for independent
// samples (more with stratified ones). One-sided log-variance-ratio test of
// H0 "ratio >= 2" at alpha = 1e-5 / 3, 100,000 estimates each (kurtosis 13
// and 6: se of the log ratio 0.013, the true ratio 31 standard errors above
// the bound). A count that ignores the lights (ratio 1) is 53 standard
// errors below it. Both means are also checked (t tests): the delta lights
// add nothing. Power (99%): a true ratio of 1.83 or less fails; the means,
// a bias of 8.2% and 4.7%. Boundary: N must grow with the number of lights.
GRADED_TEST(HemisphereLighting, SampleCountGrowsWithTheLights, "P3T3", 1, Hidden) {
  Lit one = moderate_light();
  Lit three = make_lit({0, 0, 0}, {0, 0, 1}, [](Scene& s) {
    s.add_area_light(Spectrum(5.0), {0, 0, 1}, {0.8, 0, 0}, {0, -0.6, 0});
    s.add_light<PointLight>(Spectrum(2.0), Vec3(1.0, 0.5, 0.8));
    s.add_light<DirectionalLight>(Spectrum(1.0), Vec3(0.3, 0.1, -1.0));
  });
  stats::RunningStats a = run(one, Method::Hemisphere, settings_with(1), 100000, test::seed(3570));
  stats::RunningStats b = run(three, Method::Hemisphere, settings_with(1), 100000, test::seed(3571));
  const double alpha = alpha_each(3);
  EXPECT_TRUE(stats::check(stats::variance_ratio_at_least(
      a, b, 2.0, alpha, "Var(one area light) / Var(the same with a point and a directional light), ns_area_light = 1")))
      << "estimate_direct_lighting_hemisphere must take N = (number of lights) x ns_area_light samples: 3 here";
  const double expected =
      lambert_out(parallelogram_irradiance({0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0.8, 0, 0}, {0, -0.6, 0}, 5.0));
  EXPECT_TRUE(stats::mean_matches(a, expected, alpha, "hemisphere sampling, one area light"));
  EXPECT_TRUE(stats::mean_matches(b, expected, alpha, "hemisphere sampling, the area light and two delta lights"));
}

}  // namespace
}  // namespace pt
