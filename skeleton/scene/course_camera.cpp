#include "scene/course_camera.h"

#include <cmath>

namespace pt {

Camera course_camera(const Camera& camera, const BBox& bounds, int width, int height) {
  double tan_h = std::tan(glm::radians(camera.hfov) / 2.0), tan_v = std::tan(glm::radians(camera.vfov) / 2.0);
  const double window_aspect = double(kCourseWindowWidth) / kCourseWindowHeight;
  if (tan_h > window_aspect * tan_v) tan_v = tan_h / window_aspect;
  const double screen_distance = kCourseWindowHeight / (2.0 * tan_v);
  const double vfov = glm::degrees(2.0 * std::atan(height / (2.0 * screen_distance)));
  const double hfov = glm::degrees(2.0 * std::atan(width / (2.0 * screen_distance)));

  const Vec3 centre = bounds.empty() ? Vec3(0.0) : bounds.centroid();
  double diagonal = bounds.empty() ? 0.0 : glm::length(bounds.extent());
  if (!(diagonal > 0.0)) diagonal = 1.0;  // a point (or nothing): any distance frames it
  const Vec3 view = -camera.c2w[2];
  Vec3 up(0.0, 1.0, 0.0);
  if (glm::length(glm::cross(up, view)) < 1e-9) up = camera.c2w[1];
  return Camera(centre - 1.5 * diagonal * view, centre, up, hfov, vfov, camera.near_clip, camera.far_clip);
}

}  // namespace pt
