// Part 3: direct illumination. See handouts/part3.md.
#include "core/frame.h"
#include "core/not_implemented.h"
#include "core/sampling.h"
#include "render/pathtracer.h"

namespace pt {

Spectrum DiffuseBSDF::f(const Vec3& wo, const Vec3& wi) const {
  // TODO(P3T1): the Lambertian BSDF.
  throw NotImplemented("P3T1 DiffuseBSDF::f");
}

Spectrum DiffuseBSDF::sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const {
  // TODO(P3T1): sample *wi with sample_cosine_hemisphere, write its pdf,
  // return f(wo, *wi).
  throw NotImplemented("P3T1 DiffuseBSDF::sample_f");
}

Spectrum PathTracer::zero_bounce_radiance(const Ray& r, const Intersection& isect) const {
  // TODO(P3T2): the light emitted by the surface hit towards the ray's origin
  // (get_emission takes that direction in the local frame of isect.n).
  throw NotImplemented("P3T2 PathTracer::zero_bounce_radiance");
}

Spectrum PathTracer::estimate_direct_lighting_hemisphere(const Ray& r, const Intersection& isect, Rng& rng) const {
  // TODO(P3T3): average over max(1, number of lights x ns_area_light) directions
  // sampled uniformly on the hemisphere of isect.n: f * L_in * cos / pdf, where
  // L_in is what a ray from the hit point (offset by kRayEpsilon) sees emitted,
  // or scene->background() if it escapes.
  throw NotImplemented("P3T3 PathTracer::estimate_direct_lighting_hemisphere");
}

Spectrum PathTracer::estimate_direct_lighting_importance(const Ray& r, const Intersection& isect, Rng& rng) const {
  // TODO(P3T4): for every light take ns_area_light samples (one for a delta
  // light) with sample_L; trace a shadow ray that stops kRayEpsilon short of
  // the light; average f * L * cos / pdf per light and sum over the lights.
  throw NotImplemented("P3T4 PathTracer::estimate_direct_lighting_importance");
}

Spectrum PathTracer::one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const {
  // TODO(P3T5): the estimator that settings.direct_hemisphere_sample selects.
  throw NotImplemented("P3T5 PathTracer::one_bounce_radiance");
}

Spectrum PathTracer::estimate_direct_lighting_mis(const Ray& r, const Intersection& isect, Rng& rng) const {
  // TODO(P3T6): an extension, worth points only when your instructor says so.
  // For each of ns_area_light rounds: one light sample of every light with an
  // area (as P3T4: shadow ray, skipped below the horizon) and one BSDF sample
  // (sample_f; trace it and take the emission it sees, as P3T3), each weighted
  // by the balance heuristic: its pdf / (the sum of every area light's pdf(p, wi)
  // + the BSDF's pdf_cosine_hemisphere) at its direction. Average each strategy's
  // rounds; a delta light takes one exact sample, unweighted.
  throw NotImplemented("P3T6 PathTracer::estimate_direct_lighting_mis");
}

}  // namespace pt
