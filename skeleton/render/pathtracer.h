#pragma once
#include <functional>
#include <vector>

#include "core/rng.h"
#include "geometry/intersection.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace pt {

// A pixel's estimate and how many samples it took.
struct PixelEstimate {
  Spectrum radiance{0.0};
  int num_samples = 0;
};

// Offset that moves secondary-ray origins off the surface they leave (and
// shortens shadow rays before their target) to avoid self-intersection.
constexpr double kRayEpsilon = 1e-5;

// The estimators of the assignment. Each function below names its task; the
// students' versions live in tasks/; the course's solution, compiled, in
// prebuilt/ (the parts a test or PT_REFERENCE_PARTS takes). Randomness
// comes only from the Rng passed in, so results are reproducible per pixel.
class PathTracer {
 public:
  PathTracer(const Scene& scene, const RenderSettings& settings)
      : scene(&scene), camera(&scene.camera), settings(settings) {}
  virtual ~PathTracer() = default;

  // ---- Part 1 ----
  // P1T2: average of settings.ns_aa radiance samples through pixel (x, y),
  // (0, 0) the bottom-left pixel of a settings.width x settings.height image:
  // uniformly jittered inside the pixel, or its centre when ns_aa == 1.
  PixelEstimate raytrace_pixel(int x, int y, Rng& rng) const;

  // ---- Part 3 ----
  // P3T2: radiance emitted towards the ray origin by the surface hit.
  Spectrum zero_bounce_radiance(const Ray& r, const Intersection& isect) const;
  // P3T3: direct lighting at the hit by uniform hemisphere sampling.
  Spectrum estimate_direct_lighting_hemisphere(const Ray& r, const Intersection& isect, Rng& rng) const;
  // P3T4: direct lighting at the hit by sampling the lights.
  Spectrum estimate_direct_lighting_importance(const Ray& r, const Intersection& isect, Rng& rng) const;
  // P3T5: one of the two above, as settings.direct_hemisphere_sample says.
  Spectrum one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const;
  // P3T6 (an extension, zero points unless your instructor counts it): direct
  // lighting by multiple importance sampling (handouts/part3.md, section 13).
  // For each of settings.ns_area_light rounds, one sample of every light with
  // an area (sample_L) and one of the BSDF (sample_f), each weighted by the
  // balance heuristic, pdf / (the sum of every such light's pdf + the BSDF's
  // cosine pdf) at its direction; a delta light's one exact sample as P3T4.
  Spectrum estimate_direct_lighting_mis(const Ray& r, const Intersection& isect, Rng& rng) const;

  // ---- Part 4 ----
  // P4T1/P4T2: direct light plus recursively sampled indirect light with
  // Russian roulette; r.depth is the number of bounces still allowed.
  Spectrum at_least_one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const;
  // P4T3: radiance along a camera ray. Virtual so that tests can stand in a
  // known radiance function when they check pixel sampling.
  virtual Spectrum est_radiance_global_illumination(const Ray& r, Rng& rng) const;

  // ---- Part 5 ----
  // P5T1: like raytrace_pixel, but stops early once the pixel has converged
  // (sample_adaptively decides when).
  PixelEstimate raytrace_pixel_adaptive(int x, int y, Rng& rng) const;

  const Scene* scene;
  const Camera* camera;
  RenderSettings settings;
};

// P5T1: draws samples from next_sample in batches of samples_per_batch until
// 1.96 * sigma / sqrt(n) <= max_tolerance * mu for the illuminance of the
// samples (checked after each whole batch), or max_samples are taken (none
// when max_samples <= 0). Returns the mean radiance (black for no sample) and
// the sample count.
PixelEstimate sample_adaptively(const std::function<Spectrum()>& next_sample, int max_samples, int samples_per_batch,
                                double max_tolerance);

// ---- Part 5 extension (zero points unless your instructor counts it) ----

// One pixel's pilot: the mean and the per-sample variance of its samples'
// illuminance.
struct PilotMoments {
  double mean = 0.0;
  double variance = 0.0;
};

// P5T3: how many of `budget` samples each pixel gets (handouts/part5.md,
// section 10). Counts are whole, sum to exactly max(budget, 0), and follow
// n_p = max(1, lambda r_p) to within 1, where r_p = sqrt(variance) /
// sqrt(mean^2 + 1e-2) is the pixel's relative standard deviation (0 for a
// negative variance or a pilot that is not finite) and lambda spends the
// budget; with every r_p = 0 the budget is shared equally. A budget smaller
// than the number of pixels gives one sample each to the pixels with the
// largest r_p and none to the rest.
std::vector<int> allocate_samples(const std::vector<PilotMoments>& pilot, long long budget);

}  // namespace pt
