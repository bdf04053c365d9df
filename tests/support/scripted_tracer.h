#pragma once
// A PathTracer whose radiance estimate is a script, for the pixel-sampling
// tests (Part 1's fixed count, Part 5's adaptive count): every sample's value
// is known in advance, no test depends on random numbers, and every camera
// ray is recorded.
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

}  // namespace pt::test
