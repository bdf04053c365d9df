// Part 5's image test: the library's adaptive-sampling scene rendered small
// with the student's adaptive pixel loop (batches of 8, tolerance 0.05, at
// most 32 samples), against its stored reference (fixed sampling). Each
// pixel's noise is measured from the renders themselves, whatever number of
// samples each pixel took. The method: support/image_test.h.
#include "support/graded.h"
#include "support/image_test.h"

namespace pt {
namespace {

GRADED_TEST(ImageP5, AdaptiveSunMatchesReference, "P5T1", 1, Visible) {
  const auto adaptive = [](RenderSettings& s) {
    s.adaptive = true;
    s.samples_per_batch = 8;
    s.max_tolerance = 0.05;
  };
  EXPECT_TRUE(image_test::check({"adaptive_sun", 8, 4, 32, 9501, adaptive,
                                 "adaptive sampling (batches of 8, tolerance 0.05, at most 32 spp)"}));
}

}  // namespace
}  // namespace pt
