#pragma once
// Materials. Directions wo and wi are in the local shading frame (z = normal,
// see core/frame.h) and point away from the surface.
#include "core/rng.h"
#include "core/vec.h"

namespace pt {

class BSDF {
 public:
  virtual ~BSDF() = default;
  // Value of the BSDF for the pair of directions.
  virtual Spectrum f(const Vec3& wo, const Vec3& wi) const = 0;
  // Samples *wi, writes its pdf (solid angle) and returns f(wo, *wi).
  virtual Spectrum sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const = 0;
  // Radiance emitted along wo (local frame) from the surface; zero for
  // non-emitters. Emitters are one-sided: nothing leaves through the back.
  virtual Spectrum get_emission(const Vec3& /*wo*/) const { return Spectrum(0.0); }
};

// Lambertian reflection, optionally also emitting (a glowing wall, as in the
// white furnace test, where every surface both reflects and emits).
class DiffuseBSDF : public BSDF {
 public:
  explicit DiffuseBSDF(const Spectrum& albedo, const Spectrum& emission = Spectrum(0.0))
      : reflectance(albedo), emission(emission) {}
  // P3T1: albedo / pi.
  Spectrum f(const Vec3& wo, const Vec3& wi) const override;
  // P3T1: cosine-weighted sample (core/sampling.h) with its pdf.
  Spectrum sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const override;
  Spectrum get_emission(const Vec3& wo) const override { return wo.z > 0.0 ? emission : Spectrum(0.0); }

  Spectrum reflectance;
  Spectrum emission;
};

// A light-emitting surface that reflects nothing.
class EmissionBSDF : public BSDF {
 public:
  explicit EmissionBSDF(const Spectrum& radiance) : radiance(radiance) {}
  Spectrum f(const Vec3&, const Vec3&) const override { return Spectrum(0.0); }
  Spectrum sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const override;
  Spectrum get_emission(const Vec3& wo) const override { return wo.z > 0.0 ? radiance : Spectrum(0.0); }

  Spectrum radiance;
};

}  // namespace pt
