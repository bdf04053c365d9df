// P3T5: one_bounce_radiance uses the estimator the settings choose
// (settings.direct_hemisphere_sample, the -H flag).
//
// A point light tells the two apart exactly: light sampling gives
// (albedo/pi) I cos / d^2 with no noise, hemisphere sampling gives exactly 0.
// An area light beside it gives a mean check (t test, alpha split over the
// test's checks) that the estimate is the full direct light, not a fragment.
// Power (99%): with -H, 40,000 estimates, a bias of 4.4% (this test checks
// the choice of estimator; HemisphereLighting.* check its accuracy).
#include <cmath>

#include "common.h"
#include "one_bounce_scenes.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

GRADED_TEST(OneBounce, HemisphereSettingSamplesTheHemisphere, "P3T5", 1, Visible) {
  Lit lit = point_only();
  PathTracer tracer(lit.scene, settings_with(4, /*hemisphere=*/true));
  Rng rng(test::seed(3600));
  for (int i = 0; i < 200; ++i)
    ASSERT_EQ(estimate(tracer, lit.aim, Method::OneBounce, rng), Spectrum(0.0))
        << "with direct_hemisphere_sample set, a point light is invisible (uniform hemisphere sampling)";
  Lit both = point_and_area();
  stats::RunningStats st = run(both, Method::OneBounce, settings_with(4, true), 40000, test::seed(3601));
  EXPECT_TRUE(stats::mean_matches(st, area_out(), kAlphaTest, "one_bounce_radiance with -H: the area light only"));
}

GRADED_TEST(OneBounce, LeavesOutTheSurfacesOwnEmission, "P3T5", 1, Visible) {
  // The receiver glows (radiance 3 towards the ray) and a point light lights
  // it. one_bounce_radiance is the light reflected at the hit, never what the
  // surface emits (that is zero_bounce_radiance, which Part 4 adds once, at
  // the camera's first hit; adding it here counts every emitter twice): with
  // light sampling exactly the point light's reflection, with -H exactly 0
  // (the point light is invisible to it and nothing else emits towards the
  // receiver). Exact, no statistics: 200 estimates each, relative 1e-9.
  const Lit lit = make_lit({0, 0, 0}, kN, [](Scene& s) { s.add_light<PointLight>(Spectrum(kI), kPoint); }, Spectrum(3.0));
  for (const bool hemisphere : {false, true}) {
    PathTracer tracer(lit.scene, settings_with(4, hemisphere));
    Rng rng(test::seed(hemisphere ? 3611 : 3610));
    const double want = hemisphere ? 0.0 : point_out();
    for (int i = 0; i < 200; ++i) {
      const Spectrum L = tracer.one_bounce_radiance(lit.aim.ray, lit.aim.isect, rng);
      ASSERT_TRUE(std::abs(L.r - want) <= 1e-9 * want && L.r == L.g && L.g == L.b)
          << "one_bounce_radiance at a glowing receiver (emission 3) lit by a point light, direct_hemisphere_sample="
          << hemisphere << ": " << L << ", expected " << want
          << (L.r > want + 1.0 ? ": the surface's own emission was added; one bounce is reflected light only" : "");
    }
  }
}

}  // namespace
}  // namespace pt
