// Part 5: adaptive sampling. See handouts/part5.md.
#include <cmath>

#include "core/not_implemented.h"
#include "render/pathtracer.h"

namespace pt {

PixelEstimate sample_adaptively(const std::function<Spectrum()>& next_sample, int max_samples, int samples_per_batch,
                                double max_tolerance) {
  // TODO(P5T1): draw samples, keeping s1 and s2 (sums of illuminance and its
  // square). After each whole batch compute mu = s1/n and
  // sigma^2 = (s2 - s1^2/n)/(n - 1) (clamp it at 0: rounding can make a
  // constant pixel's variance slightly negative); stop once
  // 1.96 sigma / sqrt(n) <= max_tolerance * mu. Never take more than
  // max_samples. Return the mean radiance and n.
  throw NotImplemented("P5T1 sample_adaptively");
}

PixelEstimate PathTracer::raytrace_pixel_adaptive(int x, int y, Rng& rng) const {
  // TODO(P5T1): raytrace_pixel's sampling, with sample_adaptively deciding
  // when to stop (settings.ns_aa, samples_per_batch, max_tolerance).
  throw NotImplemented("P5T1 PathTracer::raytrace_pixel_adaptive");
}

std::vector<int> allocate_samples(const std::vector<PilotMoments>& pilot, long long budget) {
  // TODO(P5T3): an extension, worth points only when your instructor says so.
  // Each pixel's r = sqrt(variance) / sqrt(mean^2 + 1e-2) (0 when the pilot
  // is NaN or infinite, or the variance negative); counts n = max(1, lambda r)
  // rounded to whole samples that sum to exactly the budget (water-filling:
  // the pixels held at 1 leave the rest to share in proportion to r). Equal
  // shares when every r is 0; a budget below the pixel count gives 1 to the
  // largest r and 0 elsewhere.
  throw NotImplemented("P5T3 allocate_samples");
}

}  // namespace pt
