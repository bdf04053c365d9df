#pragma once
// Cameras shared by the Part 1 camera tests (P1T1).
#include <vector>

#include "support/part1_builders.h"

namespace pt::test::p1 {

// Directions are unit vectors built from a handful of flops: 1e-12 leaves
// room for any order of operations and still catches every real mistake.
constexpr double kDirTol = 1e-12;

// The camera at the origin looking down -z with +y up: c2w is the identity.
inline LookAt axis_camera(double hfov, double vfov) {
  return {Vec3(0.0), Vec3(0.0, 0.0, -1.0), Vec3(0.0, 1.0, 0.0), hfov, vfov};
}

// Camera poses that are not the identity: translated, looking along other
// axes, a z-up world, an `up` that is not orthogonal to the view direction.
inline const std::vector<LookAt> kPoses = {
    {Vec3(1.0, 2.0, 3.0), Vec3(-2.0, 0.5, -4.0), Vec3(0.0, 1.0, 0.0), 60.0, 45.0},
    {Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, 1.0), 90.0, 60.0},
    {Vec3(-3.0, 1.0, 2.0), Vec3(0.0, 0.0, 0.0), Vec3(0.2, 1.0, 0.1), 30.0, 20.0},
    {Vec3(5.0, 5.0, 5.0), Vec3(0.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0), 120.0, 90.0},
    {Vec3(0.5, -2.0, 0.0), Vec3(0.5, 3.0, 0.1), Vec3(1.0, 0.0, 0.0), 75.0, 75.0},  // looking (almost) straight up
};

}  // namespace pt::test::p1
