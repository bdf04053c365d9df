// P1T1 Camera::generate_ray: directions against the closed form
//   d = normalize(forward + (2x-1) tan(hfov/2) right + (2y-1) tan(vfov/2) up)
// with the frame (forward, right, up) computed in the test from the look-at
// parameters, for several fields of view, aspects and camera poses.
#include "camera_cases.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt::test::part1 {
namespace {

GRADED_TEST(CameraRay, CentreLooksAtTarget, "P1T1", 0.5, Visible) {
  for (const LookAt& pose : kPoses) {
    Camera cam = make_camera(pose);
    Ray r = cam.generate_ray(0.5, 0.5);
    ASSERT_TRUE(VecNear("ray direction", r.d, glm::normalize(pose.target - pose.pos), kDirTol))
        << "\nThe ray through the image centre (0.5, 0.5) must point at the camera's target.\n"
        << diagnose(cam, 0.5, 0.5, r) << "\n"
        << cam << "\ntarget " << pose.target << "\nray " << r;
  }
}

GRADED_TEST(CameraRay, BottomLeftIsImageOrigin, "P1T1", 0.5, Visible) {
  LookAt pose = axis_camera(60.0, 40.0);
  Camera cam = make_camera(pose);
  Ray r = cam.generate_ray(0.0, 0.0);
  Vec3 expected = glm::normalize(Vec3(-std::tan(glm::radians(30.0)), -std::tan(glm::radians(20.0)), -1.0));
  EXPECT_TRUE(VecNear("ray direction", r.d, expected, kDirTol))
      << "\n(x, y) = (0, 0) is the bottom-left corner of the image: x grows to the right (+x in camera space), "
         "y grows upwards (+y).\n"
      << diagnose(cam, 0.0, 0.0, r) << "\n"
      << cam << "\nray " << r;
}

GRADED_TEST(CameraRay, CornersSpanTheSensor, "P1T1", 1, Visible) {
  // Corner (x, y) of the image is sensor point ((2x-1) tan(hfov/2), (2y-1) tan(vfov/2), -1).
  struct Case {
    double hfov, vfov, aspect;  // aspect > 0: hfov comes from Camera::set_aspect
  };
  const Case cases[] = {{90.0, 90.0, 0.0}, {60.0, 40.0, 0.0}, {120.0, 30.0, 0.0}, {10.0, 150.0, 0.0},
                        {0.0, 45.0, 16.0 / 9.0}, {0.0, 60.0, 0.5}};
  for (const Case& c : cases) {
    Camera cam = make_camera(axis_camera(c.hfov, c.vfov));
    if (c.aspect > 0.0) cam.set_aspect(c.aspect);
    double tx = std::tan(glm::radians(cam.hfov) / 2.0), ty = std::tan(glm::radians(cam.vfov) / 2.0);
    for (double x : {0.0, 1.0})
      for (double y : {0.0, 1.0}) {
        Ray r = cam.generate_ray(x, y);
        Vec3 expected = glm::normalize(Vec3((2.0 * x - 1.0) * tx, (2.0 * y - 1.0) * ty, -1.0));
        ASSERT_TRUE(VecNear("ray direction", r.d, expected, kDirTol))
            << "\nCorner (" << x << ", " << y << ") must go through sensor point (" << (2.0 * x - 1.0) * tx << ", "
            << (2.0 * y - 1.0) * ty << ", -1).\n"
            << diagnose(cam, x, y, r) << "\n"
            << cam << "\nray " << r;
      }
  }
}

GRADED_TEST(CameraRay, EdgeMidpointsAreHalfFovOffAxis, "P1T1", 0.5, Visible) {
  // The middle of the right edge is hfov/2 away from the view axis, the middle
  // of the top edge vfov/2: the field of view is the full opening angle.
  for (const LookAt& pose : kPoses) {
    Camera cam = make_camera(pose);
    Vec3 forward = glm::normalize(pose.target - pose.pos);
    struct Edge {
      double x, y, half_angle;
      const char* name;
    };
    const Edge edges[] = {{1.0, 0.5, pose.hfov / 2, "right"},
                          {0.0, 0.5, pose.hfov / 2, "left"},
                          {0.5, 1.0, pose.vfov / 2, "top"},
                          {0.5, 0.0, pose.vfov / 2, "bottom"}};
    for (const Edge& e : edges) {
      Ray r = cam.generate_ray(e.x, e.y);
      double angle = glm::degrees(std::acos(glm::clamp(glm::dot(glm::normalize(r.d), forward), -1.0, 1.0)));
      ASSERT_TRUE(Near("the angle (degrees) between the view axis and the ray", angle, e.half_angle, 1e-6))
          << "\nThe ray through the middle of the " << e.name << " edge (" << e.x << ", " << e.y
          << ") is half the field of view away from the view axis.\n"
          << diagnose(cam, e.x, e.y, r) << "\n"
          << cam << "\nray " << r;
    }
  }
}

GRADED_TEST(CameraRay, DirectionIsUnitLength, "P1T1", 0.5, Visible) {
  Rng rng(seed(0x0417));
  for (const LookAt& pose : kPoses) {
    Camera cam = make_camera(pose);
    for (int k = 0; k < 50; ++k) {
      Vec2 p = rng.uniform2();
      Ray r = cam.generate_ray(p.x, p.y);
      ASSERT_TRUE(Near("|d|", glm::length(r.d), 1.0, 1e-12))
          << "\nImage point " << p << ": normalise the direction.\n"
          << cam << "\nray " << r;
    }
  }
}

GRADED_TEST(CameraRay, OriginAndClipRange, "P1T1", 0.5, Visible) {
  for (const LookAt& pose : kPoses) {
    Camera cam = make_camera(pose, 0.25, 40.0);
    for (Vec2 p : {Vec2(0.5), Vec2(0.0), Vec2(1.0, 0.3)}) {
      Ray r = cam.generate_ray(p.x, p.y);
      ASSERT_EQ(r.o, cam.pos) << "The ray starts at the camera position.\n" << cam << "\nray " << r;
      ASSERT_EQ(r.min_t, cam.near_clip) << "The ray's min_t is the near clip.\n" << cam << "\nray " << r;
      ASSERT_EQ(r.max_t, cam.far_clip) << "The ray's max_t is the far clip.\n" << cam << "\nray " << r;
    }
  }
}

}  // namespace
}  // namespace pt::test::part1
