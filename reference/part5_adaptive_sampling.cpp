// Part 5 reference: adaptive sampling by a confidence interval on illuminance.
#include <algorithm>
#include <cmath>
#include <numeric>

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

// P5T3
std::vector<int> allocate_samples(const std::vector<PilotMoments>& pilot, long long budget) {
  const size_t n = pilot.size();
  std::vector<int> counts(n, 0);
  if (n == 0 || budget <= 0) return counts;
  std::vector<double> r(n);
  for (size_t i = 0; i < n; ++i) {
    const double m = pilot[i].mean, v = pilot[i].variance;
    r[i] = std::isfinite(m) && std::isfinite(v) && v > 0 ? std::sqrt(v / (m * m + 1e-2)) : 0.0;
  }
  std::vector<size_t> by_r(n);
  std::iota(by_r.begin(), by_r.end(), size_t(0));
  std::stable_sort(by_r.begin(), by_r.end(), [&](size_t a, size_t b) { return r[a] > r[b]; });
  if (budget < (long long)n) {
    for (long long k = 0; k < budget; ++k) counts[by_r[k]] = 1;
    return counts;
  }
  // Water-filling: the k noisiest pixels get lambda r, the rest their 1, with
  // lambda = (budget - (n - k)) / (sum of the k largest r). k is the largest
  // count for which the k-th noisiest pixel still gets at least 1.
  std::vector<double> target(n, double(budget) / double(n));
  double sum = 0, lambda = 0;
  for (size_t k = 1; k <= n && r[by_r[k - 1]] > 0; ++k) {
    sum += r[by_r[k - 1]];
    const double l = double(budget - (long long)(n - k)) / sum;
    if (l * r[by_r[k - 1]] < 1.0) break;
    lambda = l;
  }
  if (lambda > 0)
    for (size_t i = 0; i < n; ++i) target[i] = std::max(1.0, lambda * r[i]);
  // Whole samples: round down, then one more each to the largest remainders.
  long long given = 0;
  for (size_t i = 0; i < n; ++i) {
    counts[i] = int(std::floor(target[i]));  // at least 1: every target is
    given += counts[i];
  }
  std::vector<size_t> by_rest(n);
  std::iota(by_rest.begin(), by_rest.end(), size_t(0));
  std::stable_sort(by_rest.begin(), by_rest.end(),
                   [&](size_t a, size_t b) { return target[a] - counts[a] > target[b] - counts[b]; });
  for (size_t k = 0; given < budget; k = (k + 1) % n) ++counts[by_rest[k]], ++given;
  for (size_t k = n; given > budget;) {  // rounding put the targets a hair over
    k = k == 0 ? n - 1 : k - 1;
    if (counts[by_rest[k]] > 1) --counts[by_rest[k]], --given;
  }
  return counts;
}

}  // namespace pt
