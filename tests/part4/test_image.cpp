// Part 4's image tests: library scenes rendered small with the student's
// global illumination and Russian roulette (depth 5, continuation 0.7, as
// the references), against the stored reference images. The method:
// support/image_test.h.
#include "support/graded.h"
#include "support/image_test.h"

namespace pt {
namespace {

// Colour bleeding between the box's walls: indirect light is a large share
// of every pixel.
GRADED_TEST(ImageP4, CornellSpheresMatchesReference, "P4T1", 1, Visible) {
  EXPECT_TRUE(image_test::check({"cornell_spheres", 4, 4, 2, 9401, {}, ""}));
}

// The bunny under a sky: paths that escape see the sky at every bounce.
GRADED_TEST(ImageP4, BunnySkyMatchesReference, "P4T3", 1, Visible) {
  EXPECT_TRUE(image_test::check({"bunny_sky", 4, 4, 2, 9411, {}, ""}));
}

}  // namespace
}  // namespace pt
