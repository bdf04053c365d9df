#pragma once
// Lights that the importance-sampling estimator samples. Each sample_L is
// paired with the pdf it reports, measured per unit solid angle at p (delta
// lights report pdf 1: their "sample" is the only direction there is).
#include "core/rng.h"
#include "core/vec.h"

namespace pt {

class Light {
 public:
  virtual ~Light() = default;
  // Picks a direction *wi (unit, world space) from p towards the light, writes
  // the distance to the sampled point (inf for lights at infinity) and the pdf,
  // and returns the radiance arriving at p along -*wi if nothing is in between.
  virtual Spectrum sample_L(const Vec3& p, Vec3* wi, double* dist_to_light, double* pdf, Rng& rng) const = 0;
  // Density of sample_L choosing direction wi from p (0 for delta lights).
  virtual double pdf(const Vec3& p, const Vec3& wi) const = 0;
  virtual bool is_delta_light() const = 0;
};

// An isotropic point source of intensity I: radiance arriving is I / d^2.
class PointLight : public Light {
 public:
  PointLight(const Spectrum& intensity, const Vec3& position) : intensity(intensity), position(position) {}
  Spectrum sample_L(const Vec3& p, Vec3* wi, double* dist, double* pdf, Rng& rng) const override;
  double pdf(const Vec3&, const Vec3&) const override { return 0.0; }
  bool is_delta_light() const override { return true; }
  Spectrum intensity;
  Vec3 position;
};

// Light from one direction (the sun): radiance arrives along `direction`.
class DirectionalLight : public Light {
 public:
  DirectionalLight(const Spectrum& radiance, const Vec3& direction)
      : radiance(radiance), direction(glm::normalize(direction)) {}
  Spectrum sample_L(const Vec3& p, Vec3* wi, double* dist, double* pdf, Rng& rng) const override;
  double pdf(const Vec3&, const Vec3&) const override { return 0.0; }
  bool is_delta_light() const override { return true; }
  Spectrum radiance;
  Vec3 direction;  // direction the light travels in
};

// A one-sided parallelogram emitter: centre `position`, edges dim_x and dim_y,
// emitting radiance into the half-space of `direction`.
class AreaLight : public Light {
 public:
  AreaLight(const Spectrum& radiance, const Vec3& position, const Vec3& direction, const Vec3& dim_x,
            const Vec3& dim_y);
  Spectrum sample_L(const Vec3& p, Vec3* wi, double* dist, double* pdf, Rng& rng) const override;
  double pdf(const Vec3& p, const Vec3& wi) const override;
  bool is_delta_light() const override { return false; }
  double area() const { return area_; }
  Spectrum radiance;
  Vec3 position, direction, dim_x, dim_y;

 private:
  double area_;
};

// Uniform radiance from every direction of the sky (environment), sampled
// uniformly over the sphere.
class SkyLight : public Light {
 public:
  explicit SkyLight(const Spectrum& radiance) : radiance(radiance) {}
  Spectrum sample_L(const Vec3& p, Vec3* wi, double* dist, double* pdf, Rng& rng) const override;
  double pdf(const Vec3& p, const Vec3& wi) const override;
  bool is_delta_light() const override { return false; }
  Spectrum radiance;
};

}  // namespace pt
