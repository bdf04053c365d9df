#pragma once
// The sky scene of the Part 4 sky tests: a floor under a uniform sky.
#include "common.h"

namespace pt::test::part4 {

inline const Spectrum kSky(0.4, 0.9, 1.6);
constexpr double kFloorAlbedo = 0.5;

// A 200 x 200 floor (z = 0, facing up) under the sky: a bounce ray from the
// floor always escapes.
inline Scene sky_over_floor() {
  Scene s;
  s.add_light<SkyLight>(kSky);
  s.add_quad({0, 0, 0}, {200, 0, 0}, {0, 200, 0}, s.add_bsdf<GuardedDiffuse>(Spectrum(kFloorAlbedo)));
  s.camera = Camera({0, 0, 1}, {0.3, 0.2, 0}, {0, 0, 1}, 40, 40);
  s.build();
  return s;
}

inline RenderSettings sky_settings(int max_depth, bool accumulate) { return gi_settings(max_depth, 1.0, accumulate); }

}  // namespace pt::test::part4
