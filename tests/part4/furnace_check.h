#pragma once
// The white-furnace mean check of the Part 4 furnace tests: a two-sided t
// test of the mean of kFurnaceSamples estimates against a closed form.
#include <sstream>

#include "common.h"

namespace pt::test::part4 {

constexpr int kFurnaceSamples = 50000;
// One t test of `entry` against `expected` for the furnace of albedo a.
inline ::testing::AssertionResult furnace_check(double a, const RenderSettings& s, Entry e, double expected,
                                                double alpha, uint64_t seed) {
  Scene scene = make_white_furnace(a, kLe);
  const Aim target = furnace_aim(scene);
  stats::RunningStats st = sample(scene, target, s, e, kFurnaceSamples, seed);
  std::ostringstream what;
  what << name(e) << " in the white furnace, albedo " << a << ", Le " << kLe << ", " << describe(s);
  return stats::mean_matches(st, expected, alpha, what.str());
}

}  // namespace pt::test::part4
