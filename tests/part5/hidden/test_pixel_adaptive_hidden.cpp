// Hidden P5T1 test: the adaptive pixel loop draws its jitter from the rng it
// is given (as raytrace_pixel must, support/scripted_tracer.h).
#include "../part5_scripted.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt {
namespace {

using test::part5::adaptive_settings;
using test::part5::alternating;
using test::part5::describe;
using test::part5::scene_with_camera;
using test::part5::ScriptedTracer;

GRADED_TEST(PixelAdaptive, UsesOnlyTheRngItIsGiven, "P5T1", 0.5, Hidden) {
  // 16 samples of pixel (5, 1) (alternating 1, 0 never meets the rule);
  // exact comparisons of the rays. Boundary: exact, fails only if the jitter
  // ignores the rng passed in (or one number in 2^32 repeats).
  const Scene scene = scene_with_camera();
  const RenderSettings s = adaptive_settings(8, 6, 16, 4, 0.05);
  EXPECT_TRUE(test::jitter_comes_from(
      [&](Rng& rng) {
        ScriptedTracer tracer(scene, s, alternating(Spectrum(1), Spectrum(0)));
        tracer.raytrace_pixel_adaptive(5, 1, rng);
        return tracer.rays;
      },
      test::seed(5104)))
      << describe(ScriptedTracer(scene, s, alternating(Spectrum(1), Spectrum(0))), 5, 1);
}

}  // namespace
}  // namespace pt
