// Hidden P4T1 test: a bounce ray that escapes adds nothing. The sky's light
// at the vertex it left was already counted as that vertex's direct light
// (the sky is in the light list), and adding it again counts it twice.
#include "../common.h"
#include "../sky_scene.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

GRADED_TEST(Sky, IsNotAddedAgainWhenABounceEscapes, "P4T1", 1, Hidden) {
  // A ray hits the floor; the floor's direct light from the sky is a S in
  // every channel (Lambertian albedo a under a hemisphere of radiance S),
  // and every bounce ray from it escapes, so bounces 2 and later are zero:
  //   max_ray_depth 1 or 3, accumulate: a S;   bounce 2 alone: exactly 0.
  // Mean checks: two-sided t tests of the green channel, n = 20000 each,
  // alpha_each(2). Light sampling of a sky (uniform sphere) gives
  // 4 a S cos(theta) on the upper half, 0 on the lower: bounded, relative
  // standard deviation 1.29, standard error 0.9% of a S. Adding the sky again
  // at an escaping bounce doubles the value (about 100 standard errors).
  // Power (99%): a bias of 6.3%.
  Scene scene = sky_over_floor();
  const Aim floor_hit = aim(scene, {0, 0, 1}, {0.3, 0.2, -1.0});
  const double expected = kFloorAlbedo * kSky.g;
  const double alpha = alpha_each(2);
  uint64_t seed = 4910;
  for (int m : {1, 3}) {
    PathTracer tracer(scene, sky_settings(m, true));
    Rng rng(test::seed(seed++));
    stats::RunningStats st;
    for (int i = 0; i < 20000; ++i) st.add(estimate_once(tracer, floor_hit, Entry::AtLeastOneBounce, rng).g);
    EXPECT_TRUE(stats::mean_matches(st, expected, alpha,
                                    "at_least_one_bounce_radiance at a floor under the sky, " + describe(tracer.settings)))
        << "expected a S: the floor's direct light; its bounce rays escape and add nothing more";
  }
  PathTracer tracer(scene, sky_settings(2, false));
  Rng rng(test::seed(seed++));
  int nonzero = 0;
  for (int i = 0; i < 200; ++i)
    nonzero += estimate_once(tracer, floor_hit, Entry::AtLeastOneBounce, rng) != Spectrum(0.0);
  EXPECT_EQ(nonzero, 0) << "bounce 2 alone at a floor under the sky must be exactly 0 (there is no second vertex: "
                           "every bounce ray escapes, and the sky it reaches was the first vertex's direct light); "
                           "estimates of 200 that were not";
}

}  // namespace
}  // namespace pt
