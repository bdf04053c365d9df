#include "render/renderer.h"

#include <chrono>
#include <string>

#include "render/budget.h"
#include "render/limits.h"
#include "render/tiles.h"

namespace pt {

RenderResult render(const PathTracer& tracer, int threads, const ProgressFn& progress) {
  const RenderSettings& s = tracer.settings;
  RenderResult result;
  if (std::string why = check_render_limits(s, threads); !why.empty()) {
    result.error = why;
    return result;
  }
  if (s.adaptive_budget > 0) return render_budgeted(tracer, threads, progress);
  result.image = Image(s.width, s.height);  // may throw std::bad_alloc: the caller says how large
  result.sample_counts.assign(size_t(s.width) * s.height, 0);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  auto pixel = [&](int x, int y, size_t i) {
    Rng rng = Rng::for_pixel(s.seed, x, y);
    PixelEstimate p = s.adaptive ? tracer.raytrace_pixel_adaptive(x, y, rng) : tracer.raytrace_pixel(x, y, rng);
    const bool finite = is_finite(p.radiance);
    result.image.pixels[i] = finite ? p.radiance : Spectrum(0.0);
    result.sample_counts[i] = p.num_samples;
    return finite;
  };
  auto tile_done = [&](int done, int total) {
    if (progress) progress(done, total, elapsed());
  };
  for_each_pixel(s.width, s.height, threads, pixel, tile_done, result);
  result.seconds = elapsed();
  return result;
}

}  // namespace pt
