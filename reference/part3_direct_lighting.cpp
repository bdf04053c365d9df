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

// P3T6 (extension): multiple importance sampling, balance heuristic. Every
// light with an area is one sampling strategy and the BSDF another, each
// taking ns_area_light samples; a sample's weight is the density of the
// strategy that drew it over the sum of all of them at its direction. Every
// strategy estimates the same thing: the light emitted towards p by the first
// surface along the direction (the sampled light's, if none is in between).
Spectrum PathTracer::estimate_direct_lighting_mis(const Ray& r, const Intersection& isect, Rng& rng) const {
  const Frame frame = Frame::from_normal(isect.n);
  const Vec3 p = r.at(isect.t);
  const Vec3 wo = frame.to_local(-r.d);
  const int m = settings.ns_area_light;
  // Every strategy's density at a direction (world and local): the BSDF's and
  // each area light's.
  auto densities = [&](const Vec3& dir, const Vec3& local) {
    double sum = pdf_cosine_hemisphere(local);
    for (const auto& light : scene->lights)
      if (!light->is_delta_light()) sum += light->pdf(p, dir);
    return sum;
  };
  // What arrives along `dir` from the first surface before `dist`, or
  // `beyond` when there is none.
  auto arriving = [&](const Vec3& dir, double dist, const Spectrum& beyond) {
    Ray ray(p, dir, dist);
    ray.min_t = kRayEpsilon;
    Intersection seen;
    if (!scene->intersect(ray, &seen)) return beyond;
    return seen.bsdf->get_emission(Frame::from_normal(seen.n).to_local(-dir));
  };
  Spectrum L(0.0);
  for (const auto& light : scene->lights) {
    const bool delta = light->is_delta_light();
    const int n = delta ? 1 : m;
    for (int i = 0; i < n; ++i) {
      Vec3 dir;
      double dist, light_pdf;
      const Spectrum Le = light->sample_L(p, &dir, &dist, &light_pdf, rng);
      const Vec3 local = frame.to_local(dir);
      if (light_pdf <= 0.0 || local.z <= 0.0) continue;
      Spectrum Li = Le;
      if (delta) {  // its one exact sample, as P3T4's: the light or nothing
        Ray to_light(p, dir, dist - kRayEpsilon);
        to_light.min_t = kRayEpsilon;
        if (scene->has_intersection(to_light)) continue;
      } else {
        Li = arriving(dir, dist - kRayEpsilon, Le);
      }
      const double weight = delta ? 1.0 : light_pdf / densities(dir, local);
      L += isect.bsdf->f(wo, local) * Li * local.z / light_pdf * weight / double(n);
    }
  }
  for (int i = 0; i < m; ++i) {
    Vec3 local;
    double bsdf_pdf;
    const Spectrum f = isect.bsdf->sample_f(wo, &local, &bsdf_pdf, rng);
    if (bsdf_pdf <= 0.0 || local.z <= 0.0) continue;
    const Vec3 dir = frame.to_world(local);
    const Spectrum Li = arriving(dir, kInf, scene->background(dir));
    L += f * Li * local.z / bsdf_pdf * (bsdf_pdf / densities(dir, local)) / double(m);
  }
  return L;
}

}  // namespace pt
