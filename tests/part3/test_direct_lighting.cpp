// P3T3 and P3T4: the means of both direct-lighting estimators against closed
// forms. Both are unbiased for area and sky lights; light sampling is exact
// for point and directional lights.
//
// Mean checks: two-sided t tests (support/statistics.h) at
// alpha_each(m) = 1 - (1 - 1e-5)^(1/m) for the m configurations of a test
// (|t| > ~4.9 fails). Sample counts: 100000 estimates of ns_area_light = 4
// samples for hemisphere sampling, 50000 for light sampling; the relative
// standard errors are then at most 2% (hemisphere sampling from the far,
// grazing point, where one sample in 170 finds the light: per-sample CV 13)
// and mostly 0.3-0.7%, so the thresholds lie at 10% relative or less, and
// every mutant of the gallery moves some configuration by 17% or more (most
// by factors: see handouts/part3.md). Run with PT_STATS_VERBOSE=1 to see
// every check's n, mean, expected, standard error, t and p.
#include "common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

constexpr double kL = 5.0;  // radiance of the area lights
constexpr int kNs = 4;      // ns_area_light of the mean tests: the 1/N averaging is exercised too

// Configurations of lambert_cases(): the light 0.8 x 0.6 at height 1 (or the
// tilted one), points below, beside, partly or wholly below the horizon,
// behind the light.
void check_lambert_cases(Method m, int n, uint64_t seed) {
  const auto cases = lambert_cases();
  for (const LambertCase& c : cases) {
    Lit lit = make_lit(c.p, c.n, [&](Scene& s) { s.add_area_light(Spectrum(kL), c.c, c.ex, c.ey); });
    const double expected = lambert_out(parallelogram_irradiance(c.p, c.n, c.c, c.ex, c.ey, kL));
    stats::RunningStats st = run(lit, m, settings_with(kNs), n, test::seed(seed++));
    EXPECT_TRUE(stats::mean_matches(st, expected, alpha_each(int(cases.size())), std::string(name(m)) + ", " + c.name))
        << "albedo " << kAlbedo << ", light radiance " << kL << ", closed form: (albedo/pi) * Lambert's irradiance";
  }
}

// Shadows: the edge occluders of occluder_cases() cut the light (the closed
// form clips the light by the plane through p and the occluder's edge) or
// pass beside every path to it (no shadow allowed); a large occluder hides
// the light entirely (exactly zero).
void check_occluders(Method m, int n, uint64_t seed) {
  const Vec3 c(0, 0, 1), ex(0.8, 0, 0), ey(0, -0.6, 0);
  const auto cases = occluder_cases();
  const double alpha = alpha_each(int(cases.size()) + 1);
  for (const OccluderCase& oc : cases) {
    Lit lit = make_lit(oc.p, oc.n, [&](Scene& s) {
      s.add_area_light(Spectrum(kL), c, ex, ey);
      oc.occluder.add_to(s);
    });
    const double expected = lambert_out(polygon_irradiance(oc.p, oc.n, oc.occluder.visible(oc.p, c, ex, ey), kL));
    stats::RunningStats st = run(lit, m, settings_with(kNs), n, test::seed(seed++));
    EXPECT_TRUE(stats::mean_matches(st, expected, alpha, std::string(name(m)) + ", " + oc.name));
  }
  Lit hidden = make_lit({0, 0, 0}, {0, 0, 1}, [&](Scene& s) {
    s.add_area_light(Spectrum(kL), c, ex, ey);
    s.add_quad({0, 0, 0.5}, {2, 0, 0}, {0, 2, 0}, s.add_bsdf<DiffuseBSDF>(Spectrum(0.0)));
  });
  stats::RunningStats st = run(hidden, m, settings_with(kNs), n / 4, test::seed(seed));
  EXPECT_TRUE(stats::mean_matches(st, 0.0, alpha, std::string(name(m)) + ", light hidden by a large occluder"));
}

// ---- P3T3: uniform hemisphere sampling -------------------------------------

GRADED_TEST(HemisphereLighting, MatchesLambertForAreaLights, "P3T3", 2, Visible) {
  check_lambert_cases(Method::Hemisphere, 100000, 3300);
}

GRADED_TEST(HemisphereLighting, ShadowsOnlyWhereAnOccluderBlocks, "P3T3", 1, Hidden) {
  check_occluders(Method::Hemisphere, 100000, 3310);
}

// A uniform sky of radiance Ls over a receiver with a black wall on one side:
// E = Ls (pi - PSA(wall)), where PSA, the projected solid angle of the wall
// clipped to the hemisphere, is polygon_irradiance with radiance 1.
Lit sky_scene(const Vec3& n, double sky) {
  return make_lit({0, 0, 0}, n, [&](Scene& s) {
    s.add_light<SkyLight>(Spectrum(sky));
    s.add_quad({1.5, 0, 0.5}, {0, 0, 1.4}, {0, 2, 0}, s.add_bsdf<DiffuseBSDF>(Spectrum(0.0)));  // wall at x = 1.5
  });
}
double sky_expected(const Vec3& n, double sky) {
  const double psa = polygon_irradiance({0, 0, 0}, glm::normalize(n), parallelogram({1.5, 0, 0.5}, {0, 0, 1.4}, {0, 2, 0}), 1.0);
  return lambert_out(sky * (kPi - psa));
}

GRADED_TEST(HemisphereLighting, SeesTheSkyWhereRaysEscape, "P3T3", 1, Hidden) {
  // Rays that leave the scene bring scene->background(): the sky. Two
  // receiver orientations, 40000 estimates each (the sky estimator's CV is
  // about 1: se 0.25%).
  const std::vector<Vec3> normals = {{0, 0, 1}, glm::normalize(Vec3(0.6, -0.2, 0.5))};
  uint64_t seed = 3320;
  for (const Vec3& n : normals) {
    Lit lit = sky_scene(n, 0.7);
    stats::RunningStats st = run(lit, Method::Hemisphere, settings_with(kNs), 40000, test::seed(seed++));
    EXPECT_TRUE(stats::mean_matches(st, sky_expected(n, 0.7), alpha_each(2), "hemisphere sampling of a sky, normal " +
                                                                                    std::to_string(n.x)));
  }
}

// ---- P3T4: light sampling ------------------------------------------------------

GRADED_TEST(LightSampling, MatchesLambertForAreaLights, "P3T4", 2, Visible) {
  check_lambert_cases(Method::Importance, 50000, 3400);
}

GRADED_TEST(LightSampling, ShadowsOnlyWhereAnOccluderBlocks, "P3T4", 1, Hidden) {
  check_occluders(Method::Importance, 50000, 3410);
}

GRADED_TEST(LightSampling, DeltaLightsAreExact, "P3T4", 1, Visible) {
  // A point light of intensity I at distance d, at angle theta from the
  // normal: L_out = (albedo/pi) I cos(theta) / d^2, exactly (one sample, no
  // randomness). Directional light of radiance Ld from angle theta:
  // (albedo/pi) Ld cos(theta). Behind the receiver: 0. A wall just behind
  // the point light (a shadow ray that does not stop at the light hits it), a
  // black quad beside the path (no false shadow), and one across it (shadow).
  const double I = 3.0, Ld = 2.0;
  const Vec3 n = glm::normalize(Vec3(0.2, -0.1, 1));
  const RenderSettings settings = settings_with(8);  // ns_area_light is for area lights only
  struct Case {
    const char* name;
    Vec3 light;  // point light position, or the direction a directional light travels
    bool point, occluded;
  };
  const std::vector<Case> cases = {
      {"point light overhead", {0.3, 0.2, 1.5}, true, false},
      {"point light at a grazing angle", {2.0, -1.0, 0.25}, true, false},
      {"point light below the horizon", {1.0, 0.0, -0.5}, true, false},
      {"point light behind an occluder", {-0.5, -0.5, 1.2}, true, true},
      {"directional light", {-0.3, 0.4, -1.0}, false, false},
      {"directional light at a grazing angle", {-1.0, 0.2, -0.12}, false, false},
      {"directional light from below", {0.0, 0.3, 1.0}, false, false},
      {"directional light behind an occluder", {0.5, 0.5, -1.0}, false, true},
  };
  for (const Case& c : cases) {
    const Vec3 wi = c.point ? glm::normalize(c.light) : -glm::normalize(c.light);
    Lit lit = make_lit({0, 0, 0}, n, [&](Scene& s) {
      const BSDF* black = s.add_bsdf<DiffuseBSDF>(Spectrum(0.0));
      if (c.point) {
        s.add_light<PointLight>(Spectrum(I), c.light);
        // A wall facing the receiver 0.3 beyond the light.
        const Vec3 a = glm::normalize(glm::cross(wi, Vec3(0.3, 0.7, 0.1)));
        s.add_quad(c.light + 0.3 * wi, 2.0 * a, 2.0 * glm::cross(wi, a), black);
      } else {
        s.add_light<DirectionalLight>(Spectrum(Ld), c.light);
      }
      // A quad across the line of the path, its edge 0.05 to the side of it.
      const Vec3 side = glm::normalize(glm::cross(wi, Vec3(0.1, 0.9, 0.3)));
      const Vec3 up = glm::cross(wi, side);
      const Vec3 mid = 0.5 * (c.point ? glm::length(c.light) : 2.0) * wi;
      s.add_quad(mid + 0.35 * side, side * 0.6, up * 0.6, black);
      if (c.occluded) s.add_quad(0.5 * wi, side * 0.3, up * 0.3, black);  // across the path itself
    });
    double expected = 0.0;
    const double cos_theta = glm::dot(n, wi);
    if (!c.occluded && cos_theta > 0.0)
      expected = lambert_out(c.point ? I * cos_theta / glm::dot(c.light, c.light) : Ld * cos_theta);
    PathTracer tracer(lit.scene, settings);
    Rng rng(test::seed(3420));
    for (int k = 0; k < 3; ++k) {  // deterministic: the same every time
      const Spectrum L = tracer.estimate_direct_lighting_importance(lit.aim.ray, lit.aim.isect, rng);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(L[ch], expected, 1e-9 * expected + 1e-15) << c.name << ", channel " << ch;
    }
  }
}

GRADED_TEST(LightSampling, SumsOverLightsAveragingEachOnItsOwn, "P3T4", 1, Hidden) {
  // Two area lights, a point light, a directional light and a sky (behind
  // a black wall at x = 1.5 that blocks part of the sky and none of the
  // other lights): the estimate is the sum of each light's own average, with
  // ns_area_light = 4 samples for each area light and the sky. 40000
  // estimates; one t test at alpha = 1e-5.
  const Vec3 n = glm::normalize(Vec3(0.1, 0.1, 1));
  const Vec3 c0(0, 0, 1), ex0(0.8, 0, 0), ey0(0, -0.6, 0);
  const Vec3 c1(-0.6, 0.4, 0.8), ex1(0.2, 0, 0.05), ey1(0, -0.2, 0);
  const Vec3 point(0.5, 0.7, 1.5), sun(0.3, -0.4, -1.0);  // neither is hidden by a light quad
  const double Lp = 4.0, Lsun = 0.6, Lsky = 0.3, L1 = 20.0;
  Lit lit = make_lit({0, 0, 0}, n, [&](Scene& s) {
    s.add_area_light(Spectrum(kL), c0, ex0, ey0);
    s.add_area_light(Spectrum(L1), c1, ex1, ey1);
    s.add_light<PointLight>(Spectrum(Lp), point);
    s.add_light<DirectionalLight>(Spectrum(Lsun), sun);
    s.add_light<SkyLight>(Spectrum(Lsky));
    s.add_quad({1.5, 0, 0.5}, {0, 0, 1.4}, {0, 2, 0}, s.add_bsdf<DiffuseBSDF>(Spectrum(0.0)));
  });
  const double E = parallelogram_irradiance({0, 0, 0}, n, c0, ex0, ey0, kL) +
                   parallelogram_irradiance({0, 0, 0}, n, c1, ex1, ey1, L1) +
                   Lp * glm::dot(n, glm::normalize(point)) / glm::dot(point, point) +
                   Lsun * glm::dot(n, -glm::normalize(sun));
  // The sky: the area lights and the wall hide parts of it (they are opaque
  // to the sky's shadow rays): E_sky = Lsky (pi - PSA(wall) - PSA(lights)).
  const double psa = polygon_irradiance({0, 0, 0}, n, parallelogram({1.5, 0, 0.5}, {0, 0, 1.4}, {0, 2, 0}), 1.0) +
                     parallelogram_irradiance({0, 0, 0}, n, c0, ex0, ey0, 1.0) +
                     parallelogram_irradiance({0, 0, 0}, n, c1, ex1, ey1, 1.0);
  const double expected = lambert_out(E + Lsky * (kPi - psa));
  stats::RunningStats st = run(lit, Method::Importance, settings_with(kNs), 40000, test::seed(3430));
  EXPECT_TRUE(stats::mean_matches(st, expected, kAlphaTest, "light sampling, five lights"));
}

}  // namespace
}  // namespace pt
