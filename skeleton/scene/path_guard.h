#pragma once
// BSDFs that count their samples along one path, and the guard they count in,
// which stops a path far longer than a correct estimator traces (a depth
// never decremented, Russian roulette that never ends a path) with a message
// that says so, instead of a path that runs for minutes. The Part 4 tests
// build their scenes from these (tests/support/part4_scenes.h); they are the
// framework's so that the grader's worker process, which holds nothing of the
// tests, rebuilds the very same BSDFs from a scene that crossed to it
// (autograder/boundary/README.md). The guard stops paths; it credits
// nothing: no test passes on its word.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "scene/bsdf.h"

namespace pt {

// BSDF samples taken since the last reset(), on this thread, and the number
// allowed; `why` says which configuration the limit is for.
struct PathGuard {
  struct Stopped : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

  int64_t samples = 0;
  int64_t limit = 1 << 20;
  std::string why;

  void reset(int64_t new_limit, std::string reason) {
    samples = 0;
    limit = new_limit;
    why = std::move(reason);
  }
  void count() {
    if (++samples > limit)
      throw Stopped("path guard: one estimate sampled a BSDF more than " + std::to_string(limit) + " times (" + why +
                    "): is r.depth decremented at every bounce, does the recursion stop when it runs out, and does "
                    "Russian roulette end paths with probability 1 - rr_continue_prob?");
  }
};

inline PathGuard& path_guard() {
  thread_local PathGuard g;
  return g;
}

// Lambertian, counting its samples in the guard. It holds the diffuse BSDF
// rather than being one: a qualified call `DiffuseBSDF::sample_f` on it,
// which skips a subclass's override, has no DiffuseBSDF to reach (a
// dynamic_cast finds none), so every sample counts.
class GuardedDiffuse : public BSDF {
 public:
  explicit GuardedDiffuse(const Spectrum& albedo, const Spectrum& emission = Spectrum(0.0))
      : lambertian_(albedo, emission) {}
  Spectrum f(const Vec3& wo, const Vec3& wi) const override { return lambertian_.f(wo, wi); }
  Spectrum sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const override {
    path_guard().count();
    return lambertian_.sample_f(wo, wi, pdf, rng);
  }
  Spectrum get_emission(const Vec3& wo) const override { return lambertian_.get_emission(wo); }
  Spectrum albedo() const { return lambertian_.reflectance; }
  Spectrum emission() const { return lambertian_.emission; }

 private:
  DiffuseBSDF lambertian_;
};

// A "normal mirror": a delta BSDF that sends all light along the surface
// normal. sample_f returns wi = (0, 0, 1) with pdf 1 and value 1, so that
// f cos / pdf = 1 exactly (the delta-BSDF convention: pdf reported as 1, the
// weight folded into f). f() of any other pair is 0 (within 1e-9 of the normal
// it is 1, so that re-evaluating f at the sampled direction agrees), so
// direct light at a mirror is exactly zero: a mirror vertex passes light on
// but never gathers any. Counts its samples in the guard.
class NormalMirror : public BSDF {
 public:
  Spectrum f(const Vec3&, const Vec3& wi) const override { return Spectrum(wi.z > 1.0 - 1e-9 ? 1.0 : 0.0); }
  Spectrum sample_f(const Vec3&, Vec3* wi, double* pdf, Rng&) const override {
    path_guard().count();
    *wi = Vec3(0, 0, 1);
    *pdf = 1.0;
    return Spectrum(1.0);
  }
};

}  // namespace pt
