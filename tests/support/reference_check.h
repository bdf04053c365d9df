#pragma once
// Is an n-spp render a correct render of a library scene? The check that the
// library test makes and that a report can quote: the render is compared with
// the stored reference image (reference_image.h), and every difference is
// judged against what n samples per pixel explain, using the reference's
// measured per-pixel variance (error_model.h). Two kinds of evidence:
//
//  1. relMSE against the model: S <= E[S] + z sd[S] (one-sided). Catches any
//     large error, wherever it is, but not every small uniform one: a 5%
//     darker render also has 5% less noise, and its relMSE can come out lower
//     than a correct render's (it does in five of the seven library scenes).
//  2. Mean differences over regions, per channel: the whole image and each
//     cell of a grid (4 x 4 by default). For region G and channel c,
//       z = sum_G (T - R) / sqrt(sum_G sd^2 (1/n + 1/N)),
//     normal by the central limit theorem (thousands of independent pixels),
//     two-sided. A uniform 5% change shifts the whole image's z by
//     0.05 sqrt(nP) mean(R)/rms(sd): 38 to 61 for the library scenes at
//     16 spp. Differences up to sum_G (1e-6 |R| + 1e-12) count as zero: the
//     stored mean is rounded to float, and in a noise-free region (a sky)
//     every pixel's rounding has the same sign, adding up linearly; any real
//     change is far beyond it.
//
// The checks share alpha by Sidak's correction (statistics.h): a correct
// render fails with probability below alpha whatever the scene (the tests use
// alpha = 1e-5, ten times below the 1e-4 budget per graded test, as the
// statistics toolkit does, for the normal approximations in the far tail).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/image.h"
#include "support/reference_image.h"

namespace pt::library {

struct RegionDifference {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) x [y0, y1), row 0 at the top
  int channel = 0;                     // 0 red, 1 green, 2 blue
  double mean_difference = 0.0;        // mean of T - R over the region
  double z = 0.0;
  std::string describe() const;
};

struct ReferenceCheck {
  std::string name;
  int samples = 0;
  double alpha = 0.0;
  size_t nonfinite = 0;  // NaN or infinite pixels in the render: a failure by themselves
  double relmse = 0.0, expected = 0.0, sd = 0.0, bound = 0.0;
  double z_relmse = 0.0;  // the one-sided normal quantile of the relMSE bound
  double z_region = 0.0;  // the two-sided threshold on |z| of every region
  std::vector<RegionDifference> regions;  // the whole image first, then the grid, per channel
  const RegionDifference& worst() const;  // largest |z|
  bool relmse_ok() const { return relmse <= bound; }
  bool regions_ok() const { return std::abs(worst().z) <= z_region; }
  bool passed() const { return nonfinite == 0 && relmse_ok() && regions_ok(); }
  std::string describe() const;  // one paragraph, every number above
};

// `test` is a render of the reference's scene at `spp` samples per pixel with
// a seed that the reference did not use. Throws std::invalid_argument when the
// sizes differ.
ReferenceCheck check_render(const Image& test, int spp, const ReferenceImage& ref, double alpha, int grid_x = 4,
                            int grid_y = 4);

::testing::AssertionResult check(const ReferenceCheck& c);

}  // namespace pt::library
