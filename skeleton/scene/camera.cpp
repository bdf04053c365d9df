#include "scene/camera.h"

#include <cmath>
#include <stdexcept>

namespace pt {

Camera::Camera(const Vec3& position, const Vec3& target, const Vec3& up, double hfov_deg, double vfov_deg,
               double near, double far)
    : pos(position), hfov(hfov_deg), vfov(vfov_deg), near_clip(near), far_clip(far) {
  Vec3 back = glm::normalize(position - target);
  Vec3 right = glm::normalize(glm::cross(up, back));
  if (!is_finite(back) || !is_finite(right))
    throw std::invalid_argument("Camera: position equals target, or up is parallel to the view direction");
  c2w = Mat3(right, glm::cross(back, right), back);
}

void Camera::set_aspect(double aspect) {
  double half_v = glm::radians(vfov) / 2.0;
  hfov = glm::degrees(2.0 * std::atan(aspect * std::tan(half_v)));
}

std::ostream& operator<<(std::ostream& os, const Camera& c) {
  return os << "camera{pos=" << c.pos << " right=" << c.c2w[0] << " up=" << c.c2w[1] << " back=" << c.c2w[2]
            << " hfov=" << c.hfov << " vfov=" << c.vfov << " clip=[" << c.near_clip << ", " << c.far_clip << "]}";
}

}  // namespace pt
