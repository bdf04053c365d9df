#pragma once
// Scenes of the P3T5 tests: a point light tells the two estimators apart
// exactly (light sampling is exact, hemisphere sampling gives exactly 0), an
// area light beside it gives a mean to check.
#include "common.h"

namespace pt::test::part3 {

inline const Vec3 kN = glm::normalize(Vec3(0.1, -0.2, 1));
inline const Vec3 kPoint(0.5, 0.3, 0.8);  // below the area light's plane: never hidden by it
constexpr double kI = 2.5;

inline Lit point_only() {
  return make_lit({0, 0, 0}, kN, [](Scene& s) { s.add_light<PointLight>(Spectrum(kI), kPoint); });
}

inline Lit point_and_area() {
  return make_lit({0, 0, 0}, kN, [](Scene& s) {
    s.add_light<PointLight>(Spectrum(kI), kPoint);
    s.add_area_light(Spectrum(5.0), {0, 0, 1}, {0.8, 0, 0}, {0, -0.6, 0});
  });
}

inline double point_out() { return lambert_out(kI * glm::dot(kN, glm::normalize(kPoint)) / glm::dot(kPoint, kPoint)); }
inline double area_out() { return lambert_out(parallelogram_irradiance({0, 0, 0}, kN, {0, 0, 1}, {0.8, 0, 0}, {0, -0.6, 0}, 5.0)); }

}  // namespace pt::test::part3
