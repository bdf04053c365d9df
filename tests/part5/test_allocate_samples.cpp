// Part 5 extension tests: allocate_samples (P5T3), counts n_p ∝ r_p with a
// floor of 1, which minimise the expected relMSE for a fixed total
// (handouts/part5.md, section 10). Extension tests: their points count only
// when the instructor counts them (pt-grade --count-extensions).
//
// Closed forms: the pilots below are chosen so that mean^2 + 1e-2 is a round
// number (mean 0.7 -> 0.5, 0.3 -> 0.1, 0.1 -> 0.02, 0.2 -> 0.05, 0 -> 0.01)
// and r = sqrt(variance / (mean^2 + 1e-2)) comes out whole.
#include <cmath>
#include <limits>
#include <vector>

#include "allocation_checks.h"
#include "core/rng.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt {
namespace {

using test::part5::describe;
using test::part5::follows_water_filling;

GRADED_EXTENSION_TEST(AllocateSamples, CountsFollowTheRelativeSd, "P5T3", 1, Visible) {
  // r = 1, 2, 3, 4 from (mean, variance) = (0.7, 0.5), (0.3, 0.4), (0.1, 0.18),
  // (0.2, 0.8): a budget of 500 gives exactly 50, 100, 150, 200. With
  // sigma / mean (no 1e-2) r would be 1.01, 2.11, 4.24, 4.47; with the
  // variance instead of its root, 1 : 4 : 9 : 16.
  const std::vector<PilotMoments> pilot = {{0.7, 0.5}, {0.3, 0.4}, {0.1, 0.18}, {0.2, 0.8}};
  const std::vector<int> counts = allocate_samples(pilot, 500);
  EXPECT_EQ(counts, (std::vector<int>{50, 100, 150, 200}))
      << describe(pilot, 500) << ": n must be proportional to r = sqrt(variance / (mean^2 + 1e-2)) = 1, 2, 3, 4";
  // Other means, r = 1, 2, 6, 4, 1300 samples.
  const std::vector<PilotMoments> other = {{0.0, 0.01}, {0.3, 0.4}, {0.7, 18.0}, {0.1, 0.32}};
  EXPECT_EQ(allocate_samples(other, 1300), (std::vector<int>{100, 200, 600, 400}))
      << describe(other, 1300) << ": r = 1, 2, 6, 4 (a mean of 0 is no reason for an infinite r: mean^2 + 1e-2)";
}

GRADED_EXTENSION_TEST(AllocateSamples, EveryPixelGetsAtLeastOneSample, "P5T3", 1, Visible) {
  // r = 0, 0, 1, 3 and 22 samples: the two noise-free pixels keep 1 each, the
  // other 20 go 1 : 3, so 5 and 15 (lambda = 5, not 22 / 4 = 5.5).
  const std::vector<PilotMoments> floors = {{0.5, 0.0}, {2.0, 0.0}, {0.7, 0.5}, {0.7, 4.5}};
  EXPECT_EQ(allocate_samples(floors, 22), (std::vector<int>{1, 1, 5, 15})) << describe(floors, 22);
  // r = 0.1, 1, 1 and 12 samples: proportional shares would give the first
  // 0.57, so it is held at 1 and the others share 11: 5.5 each (5 and 6).
  const std::vector<PilotMoments> low = {{0.7, 0.005}, {0.7, 0.5}, {0.7, 0.5}};
  EXPECT_TRUE(follows_water_filling(low, 12, allocate_samples(low, 12)));
  // Many pixels at the floor: 90 noise-free, 10 noisy, 200 samples. Each
  // noisy one gets (200 - 90) / 10 = 11.
  std::vector<PilotMoments> mostly_flat(100, PilotMoments{0.5, 0.0});
  for (int i = 0; i < 100; i += 10) mostly_flat[size_t(i)] = {0.7, 0.5 * (1 + i / 10)};
  EXPECT_TRUE(follows_water_filling(mostly_flat, 200, allocate_samples(mostly_flat, 200)));
}

GRADED_EXTENSION_TEST(AllocateSamples, SpendsTheBudgetOnRandomImages, "P5T3", 1, Visible) {
  // 40 random images of 1 to 300 pixels, a third of them noise-free, budgets
  // from the pixel count to 64 per pixel. Deterministic: a fixed seed.
  Rng rng(test::seed(5301));
  for (int image = 0; image < 40; ++image) {
    const size_t n = 1 + size_t(rng.uniform() * 300);
    std::vector<PilotMoments> pilot(n);
    for (auto& p : pilot) {
      p.mean = 2.0 * rng.uniform();
      p.variance = rng.uniform() < 1.0 / 3.0 ? 0.0 : std::pow(10.0, 4.0 * rng.uniform() - 3.0);
    }
    const long long budget = (long long)n + (long long)(rng.uniform() * 63.0 * double(n));
    ASSERT_TRUE(follows_water_filling(pilot, budget, allocate_samples(pilot, budget))) << "image " << image;
  }
}

GRADED_EXTENSION_TEST(AllocateSamples, BrokenPilotsGetTheFloor, "P5T3", 1, Visible) {
  // A NaN or infinite mean or variance, or a variance a hair below 0 (what
  // rounding leaves of a constant pixel), says nothing about the noise: r = 0,
  // one sample. The last pixel (r = 2) takes the rest.
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<PilotMoments> broken = {{nan, 1.0}, {0.5, nan}, {inf, 1.0}, {0.5, inf}, {0.5, -1e-17}, {0.3, 0.4}};
  EXPECT_EQ(allocate_samples(broken, 30), (std::vector<int>{1, 1, 1, 1, 1, 25}))
      << describe(broken, 30) << ": a pilot that is not finite, or a negative variance, gives r = 0";
  // No pixels, no budget, a negative budget: nothing to give.
  EXPECT_TRUE(allocate_samples({}, 100).empty()) << "no pixels: no counts";
  EXPECT_EQ(allocate_samples(broken, 0), std::vector<int>(6, 0)) << describe(broken, 0);
  EXPECT_EQ(allocate_samples(broken, -5), std::vector<int>(6, 0)) << describe(broken, -5) << ": spend max(budget, 0)";
}

GRADED_EXTENSION_TEST(AllocateSamples, ABudgetBelowThePixelCount, "P5T3", 1, Visible) {
  // 10 pixels, 3 samples: one each to the three largest r (pixels 7, 2, 9),
  // none to the others.
  std::vector<PilotMoments> pilot(10, PilotMoments{0.7, 0.5});  // r = 1
  pilot[7] = {0.7, 8.0};                                        // r = 4
  pilot[2] = {0.7, 4.5};                                        // r = 3
  pilot[9] = {0.7, 2.0};                                        // r = 2
  std::vector<int> expected(10, 0);
  expected[7] = expected[2] = expected[9] = 1;
  EXPECT_EQ(allocate_samples(pilot, 3), expected) << describe(pilot, 3, 10);
  // Every r equal (all noise-free): 10 samples over 3 pixels, 3 or 4 each.
  const std::vector<PilotMoments> flat(3, PilotMoments{0.5, 0.0});
  const std::vector<int> shares = allocate_samples(flat, 10);
  ASSERT_EQ(shares.size(), 3u);
  EXPECT_EQ(shares[0] + shares[1] + shares[2], 10) << describe(flat, 10);
  for (int s : shares) EXPECT_TRUE(s == 3 || s == 4) << describe(flat, 10) << ": equal shares, got " << s;
}

}  // namespace
}  // namespace pt
