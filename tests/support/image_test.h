#pragma once
// The graded image tests: a library scene (scenes/library.json) rendered
// small, with this binary's parts, judged against its stored reference image.
//
// What the stored reference means at the test's size. The reference is the
// mean of N samples per pixel at 256 x 192. A render at (256/k) x (192/k)
// jitters its samples uniformly over a pixel that covers exactly k x k stored
// pixels, so its expected value is their average: the reference is
// block-averaged, and its own noise there is mean(sd^2) / (N k^2) from the
// stored per-sample sd image.
//
// What noise the render has. The test makes K independent renders (seeds
// test::seed(base + r)) of n samples per pixel each and takes their mean; each
// pixel's variance is estimated from its own K values; a region's is never
// taken below the solution's (the stored sd, image_test.cpp), which guards
// the self-normalised test's lower tail. So the null hypothesis is only "the
// render's expected value is the reference's", whatever the student's
// estimator's variance (when it is at least the solution's): a
// correct estimator other than the solution's (uniform hemisphere sampling
// (-H), an adaptive pixel loop) is tested with its own noise, and a bug that
// only adds noise is not what this test is for. n >= 2: a pixel of one
// sample is sampled at its centre (P1T2), a different expected value.
//
// The test. Regions at three scales, per channel: the whole image, a 2 x 2
// and a 4 x 4 grid (21 regions, 126 tests), each a Welch t test of
//   t = sum_G w_p (T - R) / sqrt(sum_G w_p^2 (s_p^2 / K + ref_var_p)),
// with Welch-Satterthwaite degrees of freedom (the per-pixel variances are
// estimated from K values each, pooled over the region's pixels). The
// weights w_p are 1 (the plain sum) or, in a second test of each region, the
// inverse of the solution's per-sample variance at this size, from the stored
// images alone (image_test.cpp): the weighted sum is not drowned by a few
// noisy pixels (a light's edge, fireflies), the plain one sees what changes
// those (an edge aliased, a light too bright), each catching gallery bugs the
// other misses. No test of
// single pixels: at a few samples per pixel a pixel's mean is far from normal
// (a firefly is one sample), and a per-pixel z at a Sidak-corrected 5 sigma
// would fail correct renders far more often than it claims; a region sums
// tens to thousands of independent pixels. The 126 tests share
// alpha = 1e-5 (Sidak), ten times below the 1e-4 false-failure budget of a
// graded test, for the normal approximation's far tail (the statistics
// toolkit's convention). Differences up to sum_G (1e-6 |R| + 1e-12) count as
// zero (the stored mean is float: reference_check.h).
//
// A failure names the region and writes the render, the reference, a
// difference image and a p-value image (image_test_files.h).
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/image.h"
#include "render/settings.h"

namespace pt::image_test {

struct Spec {
  std::string scene;         // a library scene's name
  int downscale = 8;         // k: the render is (256/k) x (192/k), k divides both
  int renders = 4;           // K independent renders
  int spp = 2;               // samples per pixel of each (the cap when adaptive)
  uint64_t seed = 0;         // render r uses test::seed(seed + r)
  // Settings beyond the library entry's (uniform hemisphere sampling, adaptive).
  std::function<void(RenderSettings&)> adjust;
  std::string what;          // what the settings test, for the message ("uniform hemisphere sampling")
};

struct Region {
  int grid = 1, col = 0, row = 0;  // cell (col, row) of a grid x grid division, row 0 at the top
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int channel = 0;
  bool weighted = false;  // the weighted sum, or the plain one
  double mean_difference = 0, mean_reference = 0;  // unweighted, for people
  // The weighted sum's standard error over the weighted reference of the
  // region's noisy pixels (per-sample variance above the weights' floor): a
  // noise-free pixel (a sky, a light seen directly) catches any change of its
  // own exactly, which says nothing of the test's power elsewhere.
  double relative_error = 0;
  double t = 0, dof = 0, p = 1;
  std::string describe(int width, int height) const;
};

struct Result {
  Spec spec;
  int width = 0, height = 0;
  Image render, reference;  // the render (mean of K) and the block-averaged reference
  std::vector<Region> regions;
  double alpha_each = 0;
  uint64_t nonfinite = 0;
  std::string error;        // a render or load that failed: its message (a stub names its task)
  double seconds = 0;
  const Region& worst() const;  // smallest p
  bool passed() const;
  // The smallest relative change of the noisy pixels of the whole image (one
  // channel) that fails with probability 0.99 at this render's noise: the
  // test's power.
  double detectable_change() const;
  std::string describe() const;
};

constexpr double kAlphaFamily = 1e-5;
constexpr int kGrids[] = {1, 2, 4};

Result run(const Spec& spec);
// Passes or fails with the whole description; a failure also writes its images.
::testing::AssertionResult check(const Spec& spec);

}  // namespace pt::image_test
