// Part 5 reference: adaptive sampling by a confidence interval on illuminance.
#include <algorithm>
#include <cmath>

#include "render/pathtracer.h"

namespace pt {

// P5T1
PixelEstimate sample_adaptively(const std::function<Spectrum()>& next_sample, int max_samples, int samples_per_batch,
                                double max_tolerance) {
  samples_per_batch = std::max(1, samples_per_batch);
  Spectrum sum(0.0);
  double s1 = 0.0, s2 = 0.0;  // running sums of illuminance and its square
  int n = 0;
  while (n < max_samples) {
    Spectrum x = next_sample();
    double il = illuminance(x);
    sum += x;
    s1 += il;
    s2 += il * il;
    ++n;
    if (n % samples_per_batch == 0 && n > 1) {
      double mu = s1 / n;
      double var = std::max(0.0, (s2 - s1 * s1 / n) / (n - 1));
      // 95% confidence half-width within max_tolerance of the mean.
      if (1.96 * std::sqrt(var / n) <= max_tolerance * mu) break;
    }
  }
  return {n > 0 ? sum / double(n) : Spectrum(0.0), n};
}

PixelEstimate PathTracer::raytrace_pixel_adaptive(int x, int y, Rng& rng) const {
  auto next_sample = [&] {
    Vec2 u = settings.ns_aa == 1 ? Vec2(0.5) : rng.uniform2();
    Ray r = camera->generate_ray((x + u.x) / settings.width, (y + u.y) / settings.height);
    return est_radiance_global_illumination(r, rng);
  };
  return sample_adaptively(next_sample, settings.ns_aa, settings.samples_per_batch, settings.max_tolerance);
}

}  // namespace pt
