#pragma once
// Scenes built in code for tests, where a test needs to know every number.
#include "scene/scene.h"

namespace pt::test {

// A ray and what it hits: where an estimator is evaluated at a surface point.
struct Aim {
  Ray ray;
  Intersection isect;
};

// A Cornell box: x in [-1, 1], y in [0, 2], z in [-1, 1], open at z = +1,
// walls facing inwards (red left, blue right, white elsewhere), a 0.5 x 0.5
// area light facing down just under the ceiling, two diffuse spheres. The
// camera looks in through the open side. BVH built.
Scene make_cornell_box(bool with_spheres = true);

}  // namespace pt::test
