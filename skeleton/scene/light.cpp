#include "scene/light.h"

#include "core/sampling.h"

namespace pt {

Spectrum PointLight::sample_L(const Vec3& p, Vec3* wi, double* dist, double* pdf, Rng&) const {
  Vec3 d = position - p;
  double d2 = glm::dot(d, d);
  *dist = std::sqrt(d2);
  *wi = d / *dist;
  *pdf = 1.0;
  return intensity / d2;
}

Spectrum DirectionalLight::sample_L(const Vec3&, Vec3* wi, double* dist, double* pdf, Rng&) const {
  *wi = -direction;
  *dist = kInf;
  *pdf = 1.0;
  return radiance;
}

AreaLight::AreaLight(const Spectrum& radiance, const Vec3& position, const Vec3& direction, const Vec3& dim_x,
                     const Vec3& dim_y)
    : radiance(radiance),
      position(position),
      direction(glm::normalize(direction)),
      dim_x(dim_x),
      dim_y(dim_y),
      area_(glm::length(glm::cross(dim_x, dim_y))) {}

Spectrum AreaLight::sample_L(const Vec3& p, Vec3* wi, double* dist, double* pdf, Rng& rng) const {
  Vec2 u = rng.uniform2() - Vec2(0.5);
  Vec3 d = position + u.x * dim_x + u.y * dim_y - p;
  double d2 = glm::dot(d, d);
  *dist = std::sqrt(d2);
  *wi = d / *dist;
  double cos_light = -glm::dot(*wi, direction);
  // Area to solid angle: dA = r^2 / cos(theta_light) d(omega).
  *pdf = cos_light > 0.0 ? d2 / (area_ * cos_light) : 0.0;
  return cos_light > 0.0 ? radiance : Spectrum(0.0);
}

double AreaLight::pdf(const Vec3& p, const Vec3& wi) const {
  double denom = glm::dot(wi, direction);
  if (denom >= 0.0) return 0.0;  // the light's back side, or parallel to it
  double t = glm::dot(position - p, direction) / denom;
  if (t <= 0.0) return 0.0;
  Vec3 q = p + t * wi - position;
  // Parallelogram coordinates of q by the dual basis of (dim_x, dim_y).
  Vec3 n = glm::cross(dim_x, dim_y);
  double a = glm::dot(glm::cross(q, dim_y), n) / glm::dot(n, n);
  double b = glm::dot(glm::cross(dim_x, q), n) / glm::dot(n, n);
  if (std::abs(a) > 0.5 || std::abs(b) > 0.5) return 0.0;
  return t * t / (area_ * -denom);
}

Spectrum SkyLight::sample_L(const Vec3&, Vec3* wi, double* dist, double* pdf, Rng& rng) const {
  *wi = sample_uniform_sphere(rng.uniform2());
  *dist = kInf;
  *pdf = pdf_uniform_sphere(*wi);
  return radiance;
}

double SkyLight::pdf(const Vec3&, const Vec3& wi) const { return pdf_uniform_sphere(wi); }

}  // namespace pt
