// P3T6, an extension (0 points unless the instructor counts extensions):
// direct lighting by multiple importance sampling of the lights and the BSDF,
// balance heuristic (handouts/part3.md, section 13). Its contract: unbiased
// wherever light sampling and BSDF sampling are (the means below against
// closed forms), exact for delta lights, and robust where either strategy
// alone fails: its variance is no worse than the better of the two, up to
// the additive term that bounds every balance-heuristic combination (below).
//
// Mean checks: two-sided t tests (support/statistics.h), alpha split over a
// test's checks as in test_direct_lighting.cpp. Variance checks: one-sided,
// H0 "Var(MIS) <= bound" with the bound known exactly, rejected only when the
// data show at level 1e-5 that the variance is above it
// (stats::variance_at_most; se of log s^2 from the sample's fourth moment).
//
// The bound. With one light sample and one BSDF sample per estimate
// (ns_area_light = 1), Veach's theorem (thesis, 1997, theorem 9.2) bounds the
// balance heuristic's variance by that of any other weighting of the same
// samples plus (1/min n_i - 1/sum n_i) mu^2 = mu^2 / 2; weighting one strategy
// 1 and the other 0 is such a weighting, so
//   Var(MIS) <= min(Var(light sampling), Var(BSDF sampling)) + mu^2 / 2,
// per estimate, for any correct solution, in every scene. The two scenes are
// the two strategies' known failure cases, where the worse one's variance is
// thousands of times the bound: a solution that drops either strategy, or
// weights them evenly, exceeds it. The single strategies' variances are exact:
// BSDF sampling (cosine-weighted) sees the light with the probability
// P = E / (pi L) and then gives albedo L, so Var = (albedo L)^2 P (1 - P);
// light sampling by a 400 x 400 midpoint quadrature over the light of
// (albedo/pi) L cos cos_light A / r^2 against its mean.
#include <algorithm>
#include <cmath>
#include <string>

#include "direct_checks.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

// 50,000 estimates per configuration, ns_area_light = 4: relative standard
// errors 0.02% to 0.4% (PT_STATS_VERBOSE=1). Power (99%): a bias common to
// every receiver of about 0.2%.
GRADED_EXTENSION_TEST(MisLighting, MatchesLambertForAreaLights, "P3T6", 1, Visible) {
  check_lambert_cases(Method::Mis, 50000, 3700);
}

GRADED_EXTENSION_TEST(MisLighting, DeltaLightsAreExact, "P3T6", 1, Visible) {
  // Sampling the BSDF cannot find a point or a directional light: their one
  // exact sample is all there is, with no weight (section 13).
  check_delta_lights(Method::Mis, 3710);
}

GRADED_EXTENSION_TEST(MisLighting, SumsOverLightsAndSeesEmittersThatAreNoLights, "P3T6", 1, Visible) {
  // (1) An emitting quad that is not in the light list: only BSDF samples can
  // find it, with weight 1 (no light's pdf in the sum). Lambert's value.
  // (2) Two area lights and a sky: the sum of each light's Lambert value and
  // the sky's, (albedo/pi) L_sky (pi - the lights' projected solid angles:
  // the lights hide the sky behind them). Every light's pdf is in every
  // weight's sum: a weight that leaves out the sky's (1/4pi everywhere) or
  // the other light's is biased. t tests, 100,000 estimates each, alpha split
  // 2 ways; relative standard errors about 0.3% and 0.1%.
  const double alpha = alpha_each(2);
  const Vec3 c(0, 0, 1), ex(0.8, 0, 0), ey(0, -0.6, 0);
  Lit glow = make_lit({0, 0, 0}, {0, 0, 1}, [&](Scene& s) { s.add_quad(c, ex, ey, s.add_bsdf<EmissionBSDF>(Spectrum(kL))); });
  ASSERT_TRUE(glow.scene.lights.empty());
  const double glow_expected = lambert_out(parallelogram_irradiance({0, 0, 0}, {0, 0, 1}, c, ex, ey, kL));
  EXPECT_TRUE(stats::mean_matches(run(glow, Method::Mis, settings_with(kNs), 100000, test::seed(3720)), glow_expected,
                                  alpha, "an emitting quad that is no light"))
      << "a BSDF sample that sees an emitter no light describes has weight 1: no light can sample it";

  const double L1 = 4.0, L2 = 2.5, Lsky = 0.3;
  const Vec3 c2(-0.9, 0.4, 0.7), ex2(0, 0.5, 0), ey2(0.2, 0, 0.4);  // tilted, to the side, facing the receiver
  const Vec3 n = glm::normalize(Vec3(-0.2, 0.1, 1));
  Lit lit = make_lit({0, 0, 0}, n, [&](Scene& s) {
    s.add_area_light(Spectrum(L1), c, ex, ey);
    s.add_area_light(Spectrum(L2), c2, ex2, ey2);
    s.add_light<SkyLight>(Spectrum(Lsky));
  });
  const double omega1 = parallelogram_irradiance({0, 0, 0}, n, c, ex, ey, 1.0);
  const double omega2 = parallelogram_irradiance({0, 0, 0}, n, c2, ex2, ey2, 1.0);
  const double expected = lambert_out(L1 * omega1 + L2 * omega2 + Lsky * (kPi - omega1 - omega2));
  EXPECT_TRUE(stats::mean_matches(run(lit, Method::Mis, settings_with(kNs), 100000, test::seed(3721)), expected, alpha,
                                  "two area lights and a sky"))
      << "each sample's weight is its strategy's pdf over the sum of every strategy's at its direction: the BSDF's "
         "and every light's with an area, the sky's included";
}

// One light's exact per-sample variances (the file's comment), and the bound.
struct Strategies {
  double mean, var_light, var_bsdf;
  double bound() const { return std::min(var_light, var_bsdf) + 0.5 * mean * mean; }
};

Strategies strategies(const Vec3& c, const Vec3& ex, const Vec3& ey, double L) {
  const Vec3 p(0, 0, 0), n(0, 0, 1);
  const Vec3 light_normal = glm::normalize(glm::cross(ex, ey));
  const double area = glm::length(glm::cross(ex, ey));
  const int k = 400;
  std::vector<double> h;
  h.reserve(k * k);
  double sum = 0;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const Vec3 q = c + ((i + 0.5) / k - 0.5) * ex + ((j + 0.5) / k - 0.5) * ey;
      const Vec3 d = q - p;
      const double r2 = glm::dot(d, d);
      const Vec3 w = d / std::sqrt(r2);
      const double cos_p = std::max(0.0, glm::dot(n, w)), cos_l = std::max(0.0, -glm::dot(light_normal, w));
      h.push_back(kAlbedo * kInvPi * L * cos_p * cos_l * area / r2);
      sum += h.back();
    }
  const double quadrature_mean = sum / h.size();
  double var_light = 0;
  for (double x : h) var_light += (x - quadrature_mean) * (x - quadrature_mean);
  var_light /= h.size();
  const double E = parallelogram_irradiance(p, n, c, ex, ey, L);
  const double P = E / (kPi * L);
  return {lambert_out(E), var_light, (kAlbedo * L) * (kAlbedo * L) * P * (1 - P)};
}

void check_no_worse(const Vec3& c, const Vec3& ex, const Vec3& ey, double L, int n, uint64_t seed,
                    const std::string& what) {
  const Strategies s = strategies(c, ex, ey, L);
  const Lit lit = make_lit({0, 0, 0}, {0, 0, 1}, [&](Scene& scene) { scene.add_area_light(Spectrum(L), c, ex, ey); });
  const stats::RunningStats mis = run(lit, Method::Mis, settings_with(1), n, test::seed(seed));
  EXPECT_TRUE(stats::check(stats::variance_at_most(mis, s.bound(), alpha_each(2), "Var(MIS), " + what)))
      << "Var(light sampling) = " << s.var_light << ", Var(BSDF sampling) = " << s.var_bsdf << ", mean = " << s.mean
      << ": the bound is min(the two) + mean^2 / 2, which the balance heuristic meets in any scene; above it, one "
         "strategy is missing or its weights are not the balance heuristic's";
  EXPECT_TRUE(stats::mean_matches(mis, s.mean, alpha_each(2), "MIS, " + what));
}

GRADED_EXTENSION_TEST(MisLighting, NoWorseThanLightSamplingForASmallBrightLight, "P3T6", 1, Visible) {
  // The light of HemisphereLighting.VarianceExplodesForASmallBrightLight: a
  // 0.05 x 0.05 light of radiance 960 at height 1. Per estimate: mean 0.611,
  // Var(light sampling) = 1.03e-7, Var(BSDF sampling) = 469: the bound is
  // 0.186, 2,500 times below the BSDF's. The solution's Var(MIS) is 2.9e-4.
  // 100,000 estimates of one sample of each: a BSDF sample finds the light
  // about 80 times, each then worth ~1250 times the mean when it is not
  // weighted down: a solution that samples the BSDF alone (or weights both
  // strategies alike) has a variance hundreds of times the bound, which the
  // one-sided test sees at se(log s^2) of about 0.1.
  check_no_worse({0, 0, 1}, {0.05, 0, 0}, {0, -0.05, 0}, 5.0 * 192, 100000, 3730, "a 0.05 x 0.05 light");
}

GRADED_EXTENSION_TEST(MisLighting, NoWorseThanBsdfSamplingForALargeDimLight, "P3T6", 1, Visible) {
  // A 20 x 20 light of radiance 0.5 just above the receiver (height 0.05): it
  // fills the hemisphere but for 2e-5 of its projected solid angle, so
  // cosine-weighted BSDF sampling is all but exact (Var 3.3e-6), while light
  // sampling spreads its samples over 400 units of area, of which the few
  // right above the receiver carry A cos cos_light / r^2, up to 1.6e5 (the
  // light's area over h^2) times the (albedo L / pi) of the rest: Var(light
  // sampling) = (albedo L / pi)^2 pi A / (3 h^2) - mean^2 = 2700 for an
  // unbounded light (the 400 x 400 quadrature, coarser than the peak, gives
  // 2200; either only raises min(), not the bound). Mean 0.400, bound 0.080;
  // the solution's Var(MIS) is 1.2e-3. A solution that samples the lights
  // alone has the light sampler's variance, 30,000 times the bound: about 8
  // of 100,000 estimates land within 2h of the peak, each worth a thousand
  // times the mean or more.
  check_no_worse({0, 0, 0.05}, {20, 0, 0}, {0, -20, 0}, 0.5, 100000, 3740, "a 20 x 20 light at height 0.05");
}

}  // namespace
}  // namespace pt
