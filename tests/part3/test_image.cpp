// Part 3's image tests: library scenes rendered small with the student's
// BSDF, zero-bounce radiance and direct-light estimators (the solution's
// global illumination calls them at every bounce), against the stored
// reference images. Each pixel's noise is measured from the renders
// themselves, so uniform hemisphere sampling is judged with its own noise
// against the same expected image. The method: support/image_test.h.
#include "support/graded.h"
#include "support/image_test.h"

namespace pt {
namespace {

// Light sampling with a point light (a delta light: one sample, no pdf) and
// the lamp's 1/r^2 falloff over the walls.
GRADED_TEST(ImageP3, PointLightRoomMatchesReference, "P3T4", 1, Visible) {
  EXPECT_TRUE(image_test::check({"point_light_room", 8, 4, 2, 9301, {}, ""}));
}

// Uniform hemisphere sampling (-H) under a large area light close to a wall,
// where it is least noisy, and the light itself seen by the camera.
GRADED_TEST(ImageP3, AreaLightWallHemisphereMatchesReference, "P3T3", 1, Visible) {
  const auto hemisphere = [](RenderSettings& s) { s.direct_hemisphere_sample = true; };
  EXPECT_TRUE(image_test::check({"area_light_wall", 8, 4, 2, 9311, hemisphere, "uniform hemisphere sampling (-H)"}));
}

}  // namespace
}  // namespace pt
