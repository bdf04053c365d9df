// Part 3 reference: the diffuse BSDF and direct lighting, two ways.
#include <algorithm>

#include "core/frame.h"
#include "core/sampling.h"
#include "render/pathtracer.h"

namespace pt {

// P3T1
Spectrum DiffuseBSDF::f(const Vec3& wo, const Vec3& wi) const { return reflectance * kInvPi; }

Spectrum DiffuseBSDF::sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const {
  *wi = sample_cosine_hemisphere(rng.uniform2());
  *pdf = pdf_cosine_hemisphere(*wi);
  return f(wo, *wi);
}

// P3T2
Spectrum PathTracer::zero_bounce_radiance(const Ray& r, const Intersection& isect) const {
  Frame frame = Frame::from_normal(isect.n);
  return isect.bsdf->get_emission(frame.to_local(-r.d));
}

// P3T3
Spectrum PathTracer::estimate_direct_lighting_hemisphere(const Ray& r, const Intersection& isect, Rng& rng) const {
  const Frame frame = Frame::from_normal(isect.n);
  const Vec3 hit_p = r.at(isect.t);
  const Vec3 w_out = frame.to_local(-r.d);
  // As many samples as light sampling would take for area lights, so that
  // the two estimators are compared at an equal count.
  const int n = std::max<int>(1, int(scene->lights.size()) * settings.ns_area_light);
  Spectrum L(0.0);
  for (int i = 0; i < n; ++i) {
    Vec3 w_in = sample_uniform_hemisphere(rng.uniform2());
    double pdf = pdf_uniform_hemisphere(w_in);
    Vec3 wi = frame.to_world(w_in);
    Ray shadow(hit_p, wi);
    shadow.min_t = kRayEpsilon;
    Intersection light_isect;
    Spectrum Li = scene->intersect(shadow, &light_isect)
                      ? light_isect.bsdf->get_emission(Frame::from_normal(light_isect.n).to_local(-wi))
                      : scene->background(wi);
    L += isect.bsdf->f(w_out, w_in) * Li * w_in.z / pdf;
  }
  return L / double(n);
}

// P3T4
Spectrum PathTracer::estimate_direct_lighting_importance(const Ray& r, const Intersection& isect, Rng& rng) const {
  const Frame frame = Frame::from_normal(isect.n);
  const Vec3 hit_p = r.at(isect.t);
  const Vec3 w_out = frame.to_local(-r.d);
  Spectrum L(0.0);
  for (const auto& light : scene->lights) {
    // A delta light has a single direction: more samples would repeat it.
    const int n = light->is_delta_light() ? 1 : settings.ns_area_light;
    Spectrum L_light(0.0);
    for (int i = 0; i < n; ++i) {
      Vec3 wi;
      double dist, pdf;
      Spectrum Li = light->sample_L(hit_p, &wi, &dist, &pdf, rng);
      Vec3 w_in = frame.to_local(wi);
      if (pdf <= 0.0 || w_in.z <= 0.0) continue;  // light behind the surface or facing away
      Ray shadow(hit_p, wi, dist - kRayEpsilon);
      shadow.min_t = kRayEpsilon;
      if (scene->has_intersection(shadow)) continue;
      L_light += isect.bsdf->f(w_out, w_in) * Li * w_in.z / pdf;
    }
    L += L_light / double(n);
  }
  return L;
}

// P3T5
Spectrum PathTracer::one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const {
  return settings.direct_hemisphere_sample ? estimate_direct_lighting_hemisphere(r, isect, rng)
                                           : estimate_direct_lighting_importance(r, isect, rng);
}

}  // namespace pt
