// Light from the sky (a SkyLight: uniform radiance S from every direction)
// seen by camera rays that leave the scene (P4T3): that is bounce 0, kept when
// zero-bounce light is kept (accumulate_bounces, or max_ray_depth = 0) and
// not otherwise.
#include "common.h"
#include "sky_scene.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

GRADED_TEST(Sky, ReachesTheEyeOnlyAsBounceZero, "P4T3", 1, Visible) {
  // Deterministic: an upward camera ray hits nothing, and its estimate is
  // exactly S or exactly 0 whatever random numbers are drawn.
  Scene scene = sky_over_floor();
  const Ray up({0, 0, 1}, glm::normalize(Vec3(0.2, -0.1, 1.0)));
  struct Case {
    int m;
    bool accumulate;
    Spectrum expected;
  };
  const Case cases[] = {{0, true, kSky}, {0, false, kSky}, {1, true, kSky}, {3, true, kSky},
                        {1, false, Spectrum(0.0)}, {3, false, Spectrum(0.0)}};
  Rng rng(test::seed(4900));
  for (const Case& c : cases) {
    PathTracer tracer(scene, sky_settings(c.m, c.accumulate));
    path_guard().reset(guard_limit(c.m), guard_reason(c.m, 1.0));
    const Spectrum L = tracer.est_radiance_global_illumination(up, rng);
    EXPECT_LE(glm::length(L - c.expected), 1e-12)
        << "a camera ray that escapes under a sky of radiance " << kSky << ", " << describe(tracer.settings)
        << ": expected " << c.expected << " (the sky is bounce 0, kept only with the zero bounce), got " << L;
  }
}

}  // namespace
}  // namespace pt
