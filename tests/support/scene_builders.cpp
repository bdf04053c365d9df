#include "support/scene_builders.h"

namespace pt::test {

Scene make_cornell_box(bool with_spheres) {
  Scene s;
  const BSDF* white = s.add_bsdf<DiffuseBSDF>(Spectrum(0.75));
  const BSDF* red = s.add_bsdf<DiffuseBSDF>(Spectrum(0.7, 0.1, 0.1));
  const BSDF* blue = s.add_bsdf<DiffuseBSDF>(Spectrum(0.1, 0.15, 0.7));
  // Edge order makes cross(ex, ey) point into the box.
  s.add_quad({0, 0, 0}, {0, 0, 2}, {2, 0, 0}, white);   // floor, +y
  s.add_quad({0, 2, 0}, {2, 0, 0}, {0, 0, 2}, white);   // ceiling, -y
  s.add_quad({0, 1, -1}, {2, 0, 0}, {0, 2, 0}, white);  // back, +z
  s.add_quad({-1, 1, 0}, {0, 2, 0}, {0, 0, 2}, red);    // left, +x
  s.add_quad({1, 1, 0}, {0, 0, 2}, {0, 2, 0}, blue);    // right, -x
  s.add_area_light(Spectrum(12.0), {0, 1.98, 0}, {0.5, 0, 0}, {0, 0, 0.5});
  if (with_spheres) {
    s.add_sphere({-0.45, 0.35, -0.35}, 0.35, white);
    s.add_sphere({0.45, 0.35, 0.3}, 0.35, white);
  }
  s.camera = Camera({0, 1, 3.6}, {0, 1, 0}, {0, 1, 0}, 40.0, 40.0);
  s.build();
  return s;
}

}  // namespace pt::test
