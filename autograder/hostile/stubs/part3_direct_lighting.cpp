// Part 3's stubs as the release ships them, without their comments: the base
// of the hostile cases that are an attack in an otherwise untouched submission
// (README.md beside this folder). Frozen here so that a case never changes
// when tasks/, the student's file, does.
#include "core/frame.h"
#include "core/not_implemented.h"
#include "core/sampling.h"
#include "render/pathtracer.h"

namespace pt {

Spectrum DiffuseBSDF::f(const Vec3& wo, const Vec3& wi) const {
  throw NotImplemented("P3T1 DiffuseBSDF::f");
}

Spectrum DiffuseBSDF::sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const {
  throw NotImplemented("P3T1 DiffuseBSDF::sample_f");
}

Spectrum PathTracer::zero_bounce_radiance(const Ray& r, const Intersection& isect) const {
  throw NotImplemented("P3T2 PathTracer::zero_bounce_radiance");
}

Spectrum PathTracer::estimate_direct_lighting_hemisphere(const Ray& r, const Intersection& isect, Rng& rng) const {
  throw NotImplemented("P3T3 PathTracer::estimate_direct_lighting_hemisphere");
}

Spectrum PathTracer::estimate_direct_lighting_importance(const Ray& r, const Intersection& isect, Rng& rng) const {
  throw NotImplemented("P3T4 PathTracer::estimate_direct_lighting_importance");
}

Spectrum PathTracer::one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const {
  throw NotImplemented("P3T5 PathTracer::one_bounce_radiance");
}

Spectrum PathTracer::estimate_direct_lighting_mis(const Ray& r, const Intersection& isect, Rng& rng) const {
  throw NotImplemented("P3T6 PathTracer::estimate_direct_lighting_mis");
}

}  // namespace pt
