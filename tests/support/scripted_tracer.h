#pragma once
// A PathTracer whose radiance estimate is a script, for the pixel-sampling
// tests (Part 1's fixed count, Part 5's adaptive count): every sample's value
// is known in advance, no test depends on random numbers, and every camera
// ray is recorded.
#include <gtest/gtest.h>

#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "render/pathtracer.h"

namespace pt::test {

// Sample i (counting from 0) of a pixel is value(i); text describes the
// sequence in failure messages.
struct Script {
  std::string text;
  std::function<Spectrum(int)> value;
};

inline Script constant(const Spectrum& c) {
  std::ostringstream os;
  os << "constant " << c << " (illuminance " << illuminance(c) << ")";
  return {os.str(), [c](int) { return c; }};
}

// The i-th call of the radiance estimate returns script.value(i). A pixel
// loop that ignores ns_aa is stopped by an exception after ns_aa + 1000
// calls rather than hanging the test.
class ScriptedTracer : public PathTracer {
 public:
  ScriptedTracer(const Scene& scene, const RenderSettings& s, Script script)
      : PathTracer(scene, s), script(std::move(script)) {}

  Spectrum est_radiance_global_illumination(const Ray& r, Rng&) const override {
    if (calls >= settings.ns_aa + 1000)
      throw std::runtime_error("est_radiance_global_illumination called " + std::to_string(calls) +
                               " times with ns_aa=" + std::to_string(settings.ns_aa) +
                               ": the pixel loop does not stop at ns_aa");
    rays.push_back(r);
    return script.value(calls++);
  }

  Script script;
  mutable int calls = 0;
  mutable std::vector<Ray> rays;
};

// Whether a pixel loop draws its jitter from the generator it is given, and
// only from it (the renderer seeds one per pixel and pass; that is what makes
// an image the same on any number of threads): two generators seeded alike
// give the same camera rays, one seeded otherwise gives other rays, and the
// generator passed in has moved on (a copy would hand the radiance estimates
// that follow the very numbers the jitter used). `trace(rng)` runs the loop
// once on a fresh scripted tracer and returns the rays it traced. A correct
// loop fails only if the 32-bit number drawn after its jitter equals the
// first of a fresh generator: probability 2^-32.
inline ::testing::AssertionResult jitter_comes_from(const std::function<std::vector<Ray>(Rng&)>& trace,
                                                    uint64_t seed) {
  Rng a(seed), a_again(seed), other(seed + 1), fresh(seed);
  const std::vector<Ray> ra = trace(a), ra_again = trace(a_again), r_other = trace(other);
  auto same = [](const std::vector<Ray>& x, const std::vector<Ray>& y) {
    if (x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
      if (x[i].d != y[i].d || x[i].o != y[i].o) return false;
    return true;
  };
  if (ra.empty()) return ::testing::AssertionFailure() << "no camera ray was traced";
  if (!same(ra, ra_again))
    return ::testing::AssertionFailure()
           << "two calls with generators seeded alike traced different rays: the jitter must come only from the rng "
              "passed in (no generator of your own, no static or global state)";
  if (same(ra, r_other))
    return ::testing::AssertionFailure()
           << "generators seeded differently gave the same " << ra.size()
           << " rays: the jitter does not come from the rng passed in (a generator of your own, seeded from the "
              "pixel?)";
  if (a.uniform() == fresh.uniform())
    return ::testing::AssertionFailure()
           << "the rng passed in was not advanced: the jitter came from a copy of it, so the radiance estimates "
              "that follow would draw the same numbers again (pass it on by reference)";
  return ::testing::AssertionSuccess();
}

}  // namespace pt::test
