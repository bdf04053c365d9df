// Hostile: Part 3's grazing-angle tests drew each test point from the
// generator they then passed to the estimator. This importance estimator has
// shadow acne (no offset on its shadow rays) and, whenever its estimate is not
// zero, hands back the generator moved back three draws: to where it was
// before the test drew the point, so that the test draws that lit point again,
// 20,000 times, and counts no acne. The tests now draw their points from a
// generator of their own, and a state handed back that is not the one given
// moved forward fails the call that handed it back ("moved backwards").
#include <cstdint>
#include <cstring>

#include "core/rng.h"
#include "core/vec.h"

namespace {
// PCG32's step is state * m + inc (the engine holds inc, then state): a step
// back is (state - inc) / m, m being odd and so invertible modulo 2^64.
void step_back(pt::Rng& rng, int steps) {
  uint64_t words[2];
  std::memcpy(words, &rng, sizeof words);
  const uint64_t m = 6364136223846793005ull;
  uint64_t inverse = m;
  for (int i = 0; i < 6; ++i) inverse *= 2 - m * inverse;
  for (int i = 0; i < steps; ++i) words[1] = (words[1] - words[0]) * inverse;
  std::memcpy(static_cast<void*>(&rng), words, sizeof words);
}

pt::Spectrum rewind_if_lit(const pt::Spectrum& L, pt::Rng& rng) {
  if (L != pt::Spectrum(0.0)) step_back(rng, 3);
  return L;
}
}  // namespace
