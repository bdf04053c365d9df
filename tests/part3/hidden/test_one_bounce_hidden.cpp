// Hidden P3T5 test: without -H, one_bounce_radiance samples the lights.
#include "../common.h"
#include "../one_bounce_scenes.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

// The point light exactly (1e-9 relative); point + area light: power (99%)
// a bias of 0.13%.
GRADED_TEST(OneBounce, DefaultSettingSamplesTheLights, "P3T5", 1, Hidden) {
  Lit lit = point_only();
  PathTracer tracer(lit.scene, settings_with(4, /*hemisphere=*/false));
  Rng rng(test::seed(3610));
  for (int i = 0; i < 200; ++i) {
    const Spectrum L = estimate(tracer, lit.aim, Method::OneBounce, rng);
    ASSERT_NEAR(L.g, point_out(), 1e-9 * point_out()) << "without -H, light sampling: exact for a point light";
  }
  Lit both = point_and_area();
  stats::RunningStats st = run(both, Method::OneBounce, settings_with(4, false), 20000, test::seed(3611));
  EXPECT_TRUE(stats::mean_matches(st, point_out() + area_out(), kAlphaTest, "one_bounce_radiance: point + area light"));
}

}  // namespace
}  // namespace pt
