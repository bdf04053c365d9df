#pragma once
// The worker's copies of the Part 4 tests' instrumented BSDFs
// (tests/support/part4_scenes.h): each counts its samples in a path guard that
// stops a path without Russian roulette. A callback per bounce would cost a
// round trip each, so the guard crosses as its state: the verifier sends the
// count and the limit with each estimate, the worker's copies count and stop
// the path here, and the count comes back with the answer, where the test's
// own guard then says what it says in one process (proxies_part4.cpp).
// The copies repeat the tests' few lines on purpose (the worker may hold
// nothing of the tests); every Part 4 test passing across the boundary for the
// solution (ctest boundary:*) is what shows that they behave the same.
#include <cstdint>
#include <stdexcept>

#include "scene/bsdf.h"

namespace pt::boundary {

struct PathGuardCopy {
  int64_t samples = 0;
  int64_t limit = INT64_MAX;
  void count() {
    if (++samples > limit) throw Tripped("path guard");
  }
  struct Tripped : std::runtime_error {
    using std::runtime_error::runtime_error;
  };
};

inline PathGuardCopy& path_guard_copy() {
  thread_local PathGuardCopy g;
  return g;
}

// An estimate and what the guard counted while it was taken.
struct GuardedEstimate {
  Spectrum radiance;
  int64_t samples;
  uint8_t tripped;  // the guard stopped the path: radiance means nothing
};

// GuardedDiffuse: the diffuse BSDF (the solution's, in Part 4's worker) that
// counts its samples, holding it rather than being one, as the tests' does.
class GuardedDiffuseCopy : public BSDF {
 public:
  explicit GuardedDiffuseCopy(const Spectrum& albedo, const Spectrum& emission) : lambertian_(albedo, emission) {}
  Spectrum f(const Vec3& wo, const Vec3& wi) const override { return lambertian_.f(wo, wi); }
  Spectrum sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const override {
    path_guard_copy().count();
    return lambertian_.sample_f(wo, wi, pdf, rng);
  }
  Spectrum get_emission(const Vec3& wo) const override { return lambertian_.get_emission(wo); }

 private:
  DiffuseBSDF lambertian_;
};

// NormalMirror: all light along the surface normal, f cos / pdf = 1.
class NormalMirrorCopy : public BSDF {
 public:
  Spectrum f(const Vec3&, const Vec3& wi) const override { return Spectrum(wi.z > 1.0 - 1e-9 ? 1.0 : 0.0); }
  Spectrum sample_f(const Vec3&, Vec3* wi, double* pdf, Rng&) const override {
    path_guard_copy().count();
    *wi = Vec3(0, 0, 1);
    *pdf = 1.0;
    return Spectrum(1.0);
  }
};

}  // namespace pt::boundary
