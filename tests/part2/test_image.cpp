// Part 2's image test: the bunny in the Cornell box rendered small through
// the student's BVH (its build, slab test and both traversals; the solution
// of everything else), against the stored reference image. A closest hit
// that is not the closest, or an occlusion query that misses a blocker,
// changes the image. The method: support/image_test.h.
#include "support/graded.h"
#include "support/image_test.h"

namespace pt {
namespace {

GRADED_TEST(ImageP2, CornellBunnyMatchesReference, "P2T3", 1, Visible) {
  EXPECT_TRUE(image_test::check({"cornell_bunny", 8, 4, 2, 9201, {}, ""}));
}

}  // namespace
}  // namespace pt
