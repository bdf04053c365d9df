// P3T5: one_bounce_radiance uses the estimator the settings choose
// (settings.direct_hemisphere_sample, the -H flag).
//
// A point light tells the two apart exactly: light sampling gives
// (albedo/pi) I cos / d^2 with no noise, hemisphere sampling gives exactly 0.
// An area light beside it gives a mean check (t test, alpha split over the
// test's checks) that the estimate is the full direct light, not a fragment.
#include "common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

const Vec3 kN = glm::normalize(Vec3(0.1, -0.2, 1));
const Vec3 kPoint(0.5, 0.3, 0.8);  // below the area light's plane: never hidden by it
constexpr double kI = 2.5;

Lit point_only() {
  return make_lit({0, 0, 0}, kN, [](Scene& s) { s.add_light<PointLight>(Spectrum(kI), kPoint); });
}

Lit point_and_area() {
  return make_lit({0, 0, 0}, kN, [](Scene& s) {
    s.add_light<PointLight>(Spectrum(kI), kPoint);
    s.add_area_light(Spectrum(5.0), {0, 0, 1}, {0.8, 0, 0}, {0, -0.6, 0});
  });
}

double point_out() { return lambert_out(kI * glm::dot(kN, glm::normalize(kPoint)) / glm::dot(kPoint, kPoint)); }
double area_out() { return lambert_out(parallelogram_irradiance({0, 0, 0}, kN, {0, 0, 1}, {0.8, 0, 0}, {0, -0.6, 0}, 5.0)); }

GRADED_TEST(OneBounce, HemisphereSettingSamplesTheHemisphere, "P3T5", 1, Visible) {
  Lit lit = point_only();
  PathTracer tracer(lit.scene, settings_with(4, /*hemisphere=*/true));
  Rng rng(test::seed(3600));
  for (int i = 0; i < 200; ++i)
    ASSERT_EQ(tracer.one_bounce_radiance(lit.aim.ray, lit.aim.isect, rng), Spectrum(0.0))
        << "with direct_hemisphere_sample set, a point light is invisible (uniform hemisphere sampling)";
  Lit both = point_and_area();
  stats::RunningStats st = run(both, Method::OneBounce, settings_with(4, true), 40000, test::seed(3601));
  EXPECT_TRUE(stats::mean_matches(st, area_out(), kAlphaTest, "one_bounce_radiance with -H: the area light only"));
}

GRADED_TEST(OneBounce, DefaultSettingSamplesTheLights, "P3T5", 1, Hidden) {
  Lit lit = point_only();
  PathTracer tracer(lit.scene, settings_with(4, /*hemisphere=*/false));
  Rng rng(test::seed(3610));
  for (int i = 0; i < 200; ++i) {
    const Spectrum L = tracer.one_bounce_radiance(lit.aim.ray, lit.aim.isect, rng);
    ASSERT_NEAR(L.g, point_out(), 1e-9 * point_out()) << "without -H, light sampling: exact for a point light";
  }
  Lit both = point_and_area();
  stats::RunningStats st = run(both, Method::OneBounce, settings_with(4, false), 20000, test::seed(3611));
  EXPECT_TRUE(stats::mean_matches(st, point_out() + area_out(), kAlphaTest, "one_bounce_radiance: point + area light"));
}

}  // namespace
}  // namespace pt
