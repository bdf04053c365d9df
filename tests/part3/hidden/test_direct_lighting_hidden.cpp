// Hidden P3T3 and P3T4 tests: shadows against the closed form of the
// occluded light, the sky through escaping rays, and several lights at once.
// Mean checks: two-sided t tests at alpha_each(m) for the m configurations of
// a test (common.h).
#include "../common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

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

// Relative standard errors 0.57% to 1.2%: power (99%) a bias of 4.0% in the
// best-resolved configuration.
GRADED_TEST(HemisphereLighting, ShadowsOnlyWhereAnOccluderBlocks, "P3T3", 1, Hidden) {
  check_occluders(Method::Hemisphere, 100000, 3310);
}

GRADED_TEST(HemisphereLighting, SeesTheSkyWhereRaysEscape, "P3T3", 1, Hidden) {
  // Rays that leave the scene bring scene->background(): the sky. Two
  // receiver orientations, 40000 estimates each (the sky estimator's CV is
  // about 1: se 0.17% and 0.19%). Power (99%): a bias of 1.2%.
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

// Relative standard errors 0.02% to 0.34%: power (99%) a bias of 0.16% in
// the best-resolved configuration.
GRADED_TEST(LightSampling, ShadowsOnlyWhereAnOccluderBlocks, "P3T4", 1, Hidden) {
  check_occluders(Method::Importance, 50000, 3410);
}

GRADED_TEST(LightSampling, SumsOverLightsAveragingEachOnItsOwn, "P3T4", 1, Hidden) {
  // Two area lights, a point light, a directional light and a sky (behind
  // a black wall at x = 1.5 that blocks part of the sky and none of the
  // other lights): the estimate is the sum of each light's own average, with
  // ns_area_light = 4 samples for each area light and the sky. 40000
  // estimates; one t test at alpha = 1e-5 (relative standard error 0.057%:
  // power (99%) 0.38%; averaging over all lights' samples divides by 5).
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
