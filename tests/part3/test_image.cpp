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

// Light sampling with an area light that the camera also sees: the light's
// own pixels (emission counted once, from its front) and the box it lights.
GRADED_TEST(ImageP3, CornellSpheresMatchesReference, "P3T5", 1, Visible) {
  EXPECT_TRUE(image_test::check({"cornell_spheres", 8, 4, 2, 9321, {}, ""}));
}

// Uniform hemisphere sampling (-H) under a sky: the same expected image as
// light sampling, judged with its own noise. (Not area_light_wall: there the
// hemisphere estimate near the light and the wall differs measurably from
// light sampling's, p down to 1e-7 over 200 seeds at 8 spp.)
GRADED_TEST(ImageP3, BunnySkyHemisphereMatchesReference, "P3T3", 1, Visible) {
  const auto hemisphere = [](RenderSettings& s) { s.direct_hemisphere_sample = true; };
  EXPECT_TRUE(image_test::check({"bunny_sky", 8, 4, 2, 9311, hemisphere, "uniform hemisphere sampling (-H)"}));
}

}  // namespace
}  // namespace pt
