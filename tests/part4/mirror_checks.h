#pragma once
// Exact checks on the mirror chain (support/part4_scenes.h): every one of
// kRepeats estimates must equal the expected value.
#include "common.h"

namespace pt::test::part4 {

constexpr int kRepeats = 200;

// Light sampling: exact for the point light.
inline RenderSettings chain_settings(int max_depth, double p, bool accumulate) { return gi_settings(max_depth, p, accumulate); }

// Every one of kRepeats estimates equals `expected` (to rounding).
inline ::testing::AssertionResult all_equal(const MirrorChain& chain, const RenderSettings& s, double expected,
                                            uint64_t seed) {
  PathTracer tracer(chain.scene, s);
  Rng rng(seed);
  int wrong = 0;
  Spectrum first_wrong(0.0);
  for (int i = 0; i < kRepeats; ++i) {
    const Spectrum L = estimate_once(tracer, chain.first, Entry::AtLeastOneBounce, rng);
    const bool ok = std::abs(L.r - expected) <= 1e-6 * expected + 1e-12 && L.r == L.g && L.g == L.b;
    if (!ok && wrong++ == 0) first_wrong = L;
  }
  if (wrong == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "mirror chain of " << chain.mirrors << " mirrors (light reaches the eye after exactly "
         << chain.mirrors + 1 << " bounces), " << describe(s) << ": " << wrong << " of " << kRepeats
         << " estimates of at_least_one_bounce_radiance differ from " << expected << ", the first was " << first_wrong;
}

}  // namespace pt::test::part4
