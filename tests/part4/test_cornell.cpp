// Global illumination in the Cornell box (P4T3): the bounce images of the
// renderer sum to the full render.
//
// The scene is tests/support/scene_builders.h make_cornell_box(): a 2 x 2 x 2
// box open towards the camera, red left and blue right walls, white floor,
// ceiling and back, a 0.5 x 0.5 light of radiance 12 facing down 0.02 below
// the ceiling, two white spheres. Its estimators are bounded: the light is at
// least 0.75 from every surface that sees its front, so a light sample
// (rho / pi) Le cos cos' A / r^2 is at most 1.3, and a path's weight is at
// most 0.75^4 / 0.7^3 < 1 for max_ray_depth 5 with the default p = 0.7 (the
// first bounce is not subject to roulette).
#include <vector>

#include "common.h"
#include "render/renderer.h"
#include "support/graded.h"
#include "support/scene_builders.h"

namespace pt {
namespace {

using namespace test::part4;

// ---- Graded tests -----------------------------------------------------------------

GRADED_TEST(BounceImages, SumToTheFullRender, "P4T3", 2, Visible) {
  // The renderer (render/renderer.h) makes the images of bounce k alone
  // (accumulate_bounces off, max_ray_depth = k) for k = 0 (emission seen
  // directly), 1, 2, 3, and the full render (max_ray_depth 3, accumulate
  // on): in expectation, full = b0 + b1 + b2 + b3 pixel by pixel.
  //
  // The Cornell box at 96 x 96, one sample per pixel (the pixel centre, so
  // that the emission seen directly is the same exact value in b0 and in the
  // full render: no anti-aliasing noise at the light's edge), each render
  // with its own seed, so that the per-pixel differences
  //   d = full - (b0 + b1 + b2 + b3)
  // are independent with mean 0 and bounded (every estimate here is below
  // ~2, see the top of the file). Two-sided t tests of mean(d) = 0 over the
  // whole image and over each quarter, per channel, at alpha_each(15) (Šidák
  // holds for two-sided tests of correlated normal means). The standard error
  // of mean(d) over the image is about 0.0007 (0.0014 over a quarter), against
  // an average radiance of about 0.2: keeping the first bounce instead of the
  // last, keeping every bounce up to k, or keeping the emission in every
  // bounce image all move mean(d) by tens of standard errors. Power (99%): a
  // mean difference of 0.0052 over the whole image.
  const Scene scene = test::make_cornell_box();
  const int size = 96;
  auto render_with = [&](int depth, bool accumulate, uint64_t seed) {
    RenderSettings s;
    s.width = s.height = size;
    s.ns_aa = 1;
    s.ns_area_light = 1;
    s.max_ray_depth = depth;
    s.accumulate_bounces = accumulate;
    s.seed = seed;
    RenderResult r = render(PathTracer(scene, s), 1);
    return r;
  };
  std::vector<RenderResult> bounce;
  for (int k = 0; k <= 3; ++k) {
    bounce.push_back(render_with(k, false, test::seed(5100 + k)));
    ASSERT_TRUE(bounce.back().ok()) << "render of bounce " << k << " alone failed: " << bounce.back().error;
    EXPECT_EQ(bounce.back().nonfinite_pixels, 0u) << "NaN or infinite pixels in the image of bounce " << k;
  }
  const RenderResult full = render_with(3, true, test::seed(5104));
  ASSERT_TRUE(full.ok()) << "full render failed: " << full.error;
  EXPECT_EQ(full.nonfinite_pixels, 0u) << "NaN or infinite pixels in the full render";

  struct Part {
    const char* name;
    int x0, x1, y0, y1;
  };
  const int h = size / 2;
  const Part parts[] = {{"whole image", 0, size, 0, size}, {"top-left quarter", 0, h, 0, h},
                        {"top-right quarter", h, size, 0, h}, {"bottom-left quarter", 0, h, h, size},
                        {"bottom-right quarter", h, size, h, size}};
  const double alpha = alpha_each(15);
  for (const Part& part : parts)
    for (int c = 0; c < 3; ++c) {
      stats::RunningStats d;
      for (int y = part.y0; y < part.y1; ++y)
        for (int x = part.x0; x < part.x1; ++x) {
          double sum = 0.0;
          for (const auto& b : bounce) sum += b.image.at(x, y)[c];
          d.add(full.image.at(x, y)[c] - sum);
        }
      std::ostringstream what;
      what << "full render (max_ray_depth 3) minus the sum of the images of bounces 0, 1, 2, 3 alone, per pixel, "
           << part.name << ", channel " << "RGB"[c];
      EXPECT_TRUE(stats::mean_matches(d, 0.0, alpha, what.str()));
    }
}

}  // namespace
}  // namespace pt
