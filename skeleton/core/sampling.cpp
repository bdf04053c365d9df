#include "core/sampling.h"

#include <cmath>

namespace pt {

Vec3 sample_uniform_hemisphere(const Vec2& u) {
  double z = u.x;
  double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  double phi = 2.0 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

double pdf_uniform_hemisphere(const Vec3& w) { return w.z >= 0.0 ? 0.5 * kInvPi : 0.0; }

Vec2 sample_concentric_disk(const Vec2& u) {
  Vec2 p = 2.0 * u - Vec2(1.0);
  if (p.x == 0.0 && p.y == 0.0) return {0.0, 0.0};
  double r, theta;
  if (std::abs(p.x) > std::abs(p.y)) {
    r = p.x;
    theta = (kPi / 4.0) * (p.y / p.x);
  } else {
    r = p.y;
    theta = kPi / 2.0 - (kPi / 4.0) * (p.x / p.y);
  }
  return r * Vec2(std::cos(theta), std::sin(theta));
}

Vec3 sample_cosine_hemisphere(const Vec2& u) {
  Vec2 d = sample_concentric_disk(u);
  double z = std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

double pdf_cosine_hemisphere(const Vec3& w) { return w.z >= 0.0 ? w.z * kInvPi : 0.0; }

Vec3 sample_uniform_sphere(const Vec2& u) {
  double z = 1.0 - 2.0 * u.x;
  double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  double phi = 2.0 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

double pdf_uniform_sphere(const Vec3&) { return 0.25 * kInvPi; }

}  // namespace pt
