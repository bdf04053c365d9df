#pragma once
#include "core/ray.h"

namespace pt {

// A pinhole camera. Camera space looks down -z with +y up; the sensor is the
// plane z = -1, spanning [-tan(hfov/2), tan(hfov/2)] x [-tan(vfov/2), tan(vfov/2)].
class Camera {
 public:
  Camera() = default;
  // Field-of-view angles in degrees, as in the course's scene files.
  Camera(const Vec3& position, const Vec3& target, const Vec3& up, double hfov_deg, double vfov_deg,
         double near_clip = 1e-4, double far_clip = 1e30);

  // Keeps the vertical fov and sets the horizontal one from an image aspect
  // ratio (width / height), as the renderer does for a chosen resolution.
  void set_aspect(double aspect);

  // P1T1: the ray through normalised image point (x, y) in [0,1]^2, (0,0) at the
  // bottom-left: origin at the camera position, unit direction in world space,
  // t range [near_clip, far_clip].
  Ray generate_ray(double x, double y) const;

  Vec3 pos{0.0};
  Mat3 c2w{1.0};  // columns: camera right, up and backward (+z) axes in world space
  double hfov = 50.0, vfov = 35.0;
  double near_clip = 1e-4, far_clip = 1e30;
};

std::ostream& operator<<(std::ostream& os, const Camera& c);

}  // namespace pt
