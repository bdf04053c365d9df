// Hostile: the variance tests of Part 3's light sampling ask that an estimate's
// variance fall as 1/N with ns_area_light = N. This estimator takes one light
// sample whatever N and returns the mean of its last N such estimates for the
// same ray: each answer has the variance of a mean of N, and the samples are
// fair, so the mean tests hold too. It is not a function of its arguments and
// the generator passed in: the same call from the same state is a mean over
// other samples. The grader replays calls where the worker cannot predict
// them, and the tests' own replays (tests/support/replayed_draws.h) do the same
// in one process: each test the cache answers in fails, saying so.
#include <cstddef>
#include <vector>

#include "core/vec.h"
#include "core/ray.h"

namespace {
struct Cached {
  pt::Vec3 o, d;
  int n;
  std::vector<pt::Spectrum> raw;
};

pt::Spectrum mean_of_last(const pt::Ray& r, int n, const pt::Spectrum& one_sample) {
  static std::vector<Cached> cache;
  Cached* c = nullptr;
  for (Cached& e : cache)
    if (e.o == r.o && e.d == r.d && e.n == n) c = &e;
  if (!c) {
    if (cache.size() > 64) cache.clear();
    cache.push_back({r.o, r.d, n, {}});
    c = &cache.back();
  }
  c->raw.push_back(one_sample);
  if (c->raw.size() > static_cast<size_t>(n < 1 ? 1 : n)) c->raw.erase(c->raw.begin());
  pt::Spectrum sum(0.0);
  for (const pt::Spectrum& x : c->raw) sum += x;
  return sum / double(c->raw.size());
}
}  // namespace
