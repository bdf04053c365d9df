// Hidden P1T1 tests: the whole image plane of several cameras against the
// closed form of generate_ray.
#include "../camera_cases.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt::test::part1 {
namespace {

GRADED_TEST(CameraRay, SensorIsAPlane, "P1T1", 0.5, Hidden) {
  // Image points map linearly onto the sensor plane (tangents), not onto
  // angles: (0.75, 0.5) is at tan(angle) = tan(hfov/2) / 2.
  LookAt pose = axis_camera(100.0, 70.0);
  Camera cam = make_camera(pose);
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      double x = i / 8.0, y = j / 8.0;
      Ray r = cam.generate_ray(x, y);
      ASSERT_TRUE(VecNear("ray direction", r.d, expected_direction(pose, x, y), kDirTol))
          << "\nImage point (" << x << ", " << y << ") must map linearly onto the sensor plane z = -1.\n"
          << diagnose(cam, x, y, r) << "\n"
          << cam << "\nray " << r;
    }
}

GRADED_TEST(CameraRay, PosedCameraMatchesLookAt, "P1T1", 1, Hidden) {
  Rng rng(seed(0x9a11));
  for (const LookAt& pose : kPoses) {
    Camera cam = make_camera(pose);
    for (int k = 0; k < 50; ++k) {
      Vec2 p = rng.uniform2();
      Ray r = cam.generate_ray(p.x, p.y);
      ASSERT_TRUE(VecNear("ray direction", r.d, expected_direction(pose, p.x, p.y), kDirTol))
          << "\nImage point " << p << " of a camera looking from " << pose.pos << " at " << pose.target
          << " with up " << pose.up << ".\n"
          << diagnose(cam, p.x, p.y, r) << "\n"
          << cam << "\nray " << r;
    }
  }
}

}  // namespace
}  // namespace pt::test::part1
