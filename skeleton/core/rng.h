#pragma once
// One random generator per (pixel, pass): a PCG32 stream whose seed mixes the
// render seed with the pixel and pass, so that an image does not depend on the
// thread count or on the order tiles are rendered in.
#include <cstdint>
#include <pcg_random.hpp>

#include "core/vec.h"

namespace pt {

class Rng {
 public:
  explicit Rng(uint64_t seed = 0, uint64_t stream = 0) : engine_(mix(seed), stream) {}

  // Generator for one pixel of one pass of a render.
  static Rng for_pixel(uint64_t seed, uint32_t x, uint32_t y, uint32_t pass = 0) {
    return Rng(seed ^ mix((uint64_t(x) << 32) | y), pass);
  }

  // Uniform in [0, 1): 32 random bits scaled, never exactly 1.
  double uniform() { return engine_() * 0x1p-32; }
  Vec2 uniform2() {
    double a = uniform();
    return {a, uniform()};
  }
  bool coin_flip(double p) { return uniform() < p; }

 private:
  // SplitMix64 finaliser: decorrelates nearby seeds (neighbouring pixels).
  static uint64_t mix(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  pcg32 engine_;
};

}  // namespace pt
