// Part 4: global illumination. See handouts/part4.md.
#include "core/frame.h"
#include "core/not_implemented.h"
#include "render/pathtracer.h"

namespace pt {

Spectrum PathTracer::at_least_one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const {
  // TODO(P4T1): one_bounce_radiance at this hit, plus the radiance of a
  // bounce ray sampled from the BSDF (weight f * cos / pdf) with depth
  // r.depth - 1, while depth remains. With settings.accumulate_bounces false,
  // keep only the direct light of the last bounce (r.depth == 1).
  // TODO(P4T2): Russian roulette: continue with settings.rr_continue_prob
  // (always on the first bounce) and divide survivors by that probability.
  throw NotImplemented("P4T1 PathTracer::at_least_one_bounce_radiance");
}

Spectrum PathTracer::est_radiance_global_illumination(const Ray& r, Rng& rng) const {
  // TODO(P4T3): zero-bounce radiance of the first hit (or scene->background()
  // if the ray escapes; either only while bounce 0 is kept), plus at_least_one_bounce_radiance with
  // depth = settings.max_ray_depth when that is at least 1. Without
  // accumulate_bounces, return only bounce number max_ray_depth.
  throw NotImplemented("P4T3 PathTracer::est_radiance_global_illumination");
}

}  // namespace pt
