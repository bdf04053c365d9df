#pragma once
// Cameras shared by the Part 1 camera tests (P1T1).
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "support/part1_builders.h"

namespace pt::test::part1 {

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

// What is wrong with the ray `r` that generate_ray(x, y) returned, worked
// out from the ray itself, for a failure message: the direction is compared
// with the closed form as a whole (unrotated, rotated by the inverse of c2w),
// then taken back to camera space (c2w is the framework's, from the look-at
// parameters) and its point on the sensor plane z = -1 is compared with
// ((2x-1) tan(hfov/2), (2y-1) tan(vfov/2)) one axis at a time, so that each
// hint names the component that is wrong: a flipped axis, a missing 2x - 1,
// the whole fov, degrees, the other axis's fov, angles spread linearly.
inline std::string diagnose(const Camera& cam, double x, double y, const Ray& r) {
  std::ostringstream os = stream15();
  const double len = glm::length(r.d);
  if (!is_finite(r.d) || !(len > 0.0)) {
    os << "Diagnosis: the direction " << r.d << " is not a finite, non-zero vector.";
    return os.str();
  }
  const Vec3 d = r.d / len;
  const double tx = std::tan(glm::radians(cam.hfov) / 2.0), ty = std::tan(glm::radians(cam.vfov) / 2.0);
  const Vec3 sensor((2.0 * x - 1.0) * tx, (2.0 * y - 1.0) * ty, -1.0);
  auto same = [](const Vec3& a, const Vec3& b) { return glm::length(a - b) <= 1e-9; };
  std::vector<std::string> hints;
  if (std::abs(len - 1.0) > 1e-9) hints.push_back("the direction has length " + std::to_string(len) + ": normalise it");
  const Vec3 expected = glm::normalize(cam.c2w * sensor);
  if (!same(d, expected)) {
    if (same(d, glm::normalize(sensor))) {
      hints.push_back("the direction is the camera-space one: it was not rotated into world space by c2w");
    } else if (same(d, glm::normalize(glm::transpose(cam.c2w) * sensor))) {
      hints.push_back("the direction was rotated by the inverse (transpose) of c2w: c2w takes camera space to world "
                      "space, multiply c2w * v");
    } else {
      const Vec3 dc = glm::transpose(cam.c2w) * d;  // the ray in camera space (c2w is a rotation)
      if (!(dc.z < -1e-12)) {
        std::ostringstream h = stream15();
        h << "in camera space the ray is " << dc << ", not in front of the camera: the sensor is the plane z = -1";
        hints.push_back(h.str());
      } else {
        // Each axis's point on the sensor, against what it should be.
        struct Axis {
          const char *name, *coordinate, *grows;
          double got, want, u, t, t_other, fov;
        };
        const Axis axes[] = {{"X", "x", "to the right", dc.x / -dc.z, sensor.x, x, tx, ty, cam.hfov},
                             {"Y", "y", "upwards (y = 0 is the bottom of the image)", dc.y / -dc.z, sensor.y, y, ty, tx,
                              cam.vfov}};
        for (const Axis& a : axes) {
          const double tol = 1e-9 * std::max(1.0, a.t);
          if (std::abs(a.got - a.want) <= tol) continue;
          std::ostringstream h = stream15();
          h << "on the sensor plane the ray's " << a.name << " is " << a.got << ", expected (2" << a.coordinate
            << " - 1) tan(fov/2) = " << a.want << ": ";
          const double half = glm::radians(a.fov) / 2.0, k = a.want != 0.0 ? a.got / a.want : 0.0;
          auto ratio_is = [&](double v) { return a.want != 0.0 && std::abs(k - v) <= 1e-9 * std::max(1.0, std::abs(v)); };
          if (a.want != 0.0 && std::abs(a.got + a.want) <= tol)
            h << "the axis is flipped; " << a.coordinate << " grows " << a.grows;
          else if (std::abs(a.got - a.u * a.t) <= tol)
            h << "not centred: " << a.coordinate << " in [0, 1] must map to [-tan, tan] with 2" << a.coordinate
              << " - 1";
          else if (std::abs(a.got - std::tan((2.0 * a.u - 1.0) * half)) <= tol)
            h << "the angle was spread linearly over the image; positions on the sensor plane are linear in "
              << a.coordinate << ", angles are not";
          else if (ratio_is(std::tan(2.0 * half) / a.t))
            h << "the tangent of the whole field of view; the sensor's half-width is tan(fov / 2)";
          else if (ratio_is(std::tan(a.fov / 2.0) / a.t) || ratio_is(std::tan(a.fov) / a.t))
            h << "std::tan was given degrees; convert the field of view with glm::radians";
          else if (ratio_is(a.t_other / a.t))
            h << "the other axis's field of view (hfov is horizontal, vfov vertical)";
          else if (a.want != 0.0)
            h << "scaled by " << k << "; the sensor spans +-tan(fov / 2), the fov in radians";
          else
            h << "off-centre; the middle of the image is on the view axis";
          hints.push_back(h.str());
        }
      }
    }
  }
  if (hints.empty()) return "Diagnosis: the direction is right.";
  os << "Diagnosis from the ray:";
  for (const std::string& h : hints) os << "\n  - " << h;
  return os.str();
}

}  // namespace pt::test::part1
