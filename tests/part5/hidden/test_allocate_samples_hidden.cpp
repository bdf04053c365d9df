// Hidden P5T3 test: a large image with heavy-tailed noise, where the pixels
// held at one sample and the proportional ones both matter.
#include <cmath>
#include <vector>

#include "../allocation_checks.h"
#include "core/rng.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt {
namespace {

GRADED_EXTENSION_TEST(AllocateSamples, LargeImageWithHeavyTails, "P5T3", 1, Hidden) {
  // 64 x 64 pixels: r log-uniform over six decades, a quarter noise-free,
  // budgets of 1.5, 8 and 64 samples per pixel.
  Rng rng(test::seed(5302));
  std::vector<PilotMoments> pilot(64 * 64);
  for (auto& p : pilot) {
    p.mean = rng.uniform();
    p.variance = rng.uniform() < 0.25 ? 0.0 : std::pow(10.0, 6.0 * rng.uniform() - 4.0);
  }
  for (long long per_pixel2 : {3LL, 16LL, 128LL}) {
    const long long budget = per_pixel2 * (long long)pilot.size() / 2;
    EXPECT_TRUE(test::part5::follows_water_filling(pilot, budget, allocate_samples(pilot, budget)));
  }
}

}  // namespace
}  // namespace pt
