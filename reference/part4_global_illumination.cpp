// Part 4 reference: the recursive path estimator with Russian roulette.
#include "core/frame.h"
#include "render/pathtracer.h"

namespace pt {

// P4T1, P4T2
Spectrum PathTracer::at_least_one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const {
  // r.depth bounces remain; this vertex's direct light is bounce number
  // max_ray_depth - r.depth + 1, which is the last one when r.depth == 1.
  Spectrum L(0.0);
  if (settings.accumulate_bounces || r.depth == 1) L += one_bounce_radiance(r, isect, rng);
  if (r.depth <= 1) return L;

  const Frame frame = Frame::from_normal(isect.n);
  Vec3 w_in;
  double pdf;
  Spectrum f = isect.bsdf->sample_f(frame.to_local(-r.d), &w_in, &pdf, rng);
  if (pdf <= 0.0 || f == Spectrum(0.0)) return L;

  // Russian roulette, never on the first bounce: a path survives with
  // probability p and its contribution is divided by p, so the mean stays.
  const bool first_bounce = r.depth == settings.max_ray_depth;
  const double p = first_bounce ? 1.0 : settings.rr_continue_prob;
  if (!first_bounce && !rng.coin_flip(p)) return L;

  Vec3 wi = frame.to_world(w_in);
  Ray bounce(r.at(isect.t), wi, kInf, r.depth - 1);
  bounce.min_t = kRayEpsilon;
  Intersection next;
  if (!scene->intersect(bounce, &next)) return L;  // light from the sky was counted as direct light
  return L + f * at_least_one_bounce_radiance(bounce, next, rng) * (w_in.z / (pdf * p));
}

// P4T3
Spectrum PathTracer::est_radiance_global_illumination(const Ray& r, Rng& rng) const {
  const bool keep_zero = settings.accumulate_bounces || settings.max_ray_depth == 0;
  Intersection isect;
  if (!scene->intersect(r, &isect)) return keep_zero ? scene->background(r.d) : Spectrum(0.0);
  Spectrum L = keep_zero ? zero_bounce_radiance(r, isect) : Spectrum(0.0);
  if (settings.max_ray_depth >= 1) {
    Ray ray = r;
    ray.depth = settings.max_ray_depth;
    L += at_least_one_bounce_radiance(ray, isect, rng);
  }
  return L;
}

}  // namespace pt
