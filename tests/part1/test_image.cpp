// Part 1's image tests: library scenes rendered small with the student's
// camera, pixel loop, triangles and spheres (the solution's BVH, lights and
// estimators), against the stored reference images. The method, its
// threshold and what the reference means at this size: support/image_test.h.
#include "support/graded.h"
#include "support/image_test.h"

namespace pt {
namespace {

// The Cornell box with two spheres: every camera ray and every bounce meets
// the box's triangles and the spheres, and each wall's colour bleeds onto
// its neighbours; a wrong hit, normal or range anywhere shows as a region.
GRADED_TEST(ImageP1, CornellSpheresMatchesReference, "P1T4", 1, Visible) {
  EXPECT_TRUE(image_test::check({"cornell_spheres", 16, 4, 2, 9101, {}, ""}));
}

// The bunny in the box: thousands of small triangles (interpolated normals,
// edges shared by neighbours) between the camera and the walls.
GRADED_TEST(ImageP1, CornellBunnyMatchesReference, "P1T3", 1, Visible) {
  EXPECT_TRUE(image_test::check({"cornell_bunny", 8, 2, 2, 9111, {}, ""}));
}

}  // namespace
}  // namespace pt
