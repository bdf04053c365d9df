#include "render/renderer.h"

#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <string>

#include "render/limits.h"
#include "render/worker_threads.h"

namespace pt {

namespace {
constexpr int kTile = 16;
}

RenderResult render(const PathTracer& tracer, int threads, const ProgressFn& progress) {
  const RenderSettings& s = tracer.settings;
  RenderResult result;
  if (std::string why = check_render_limits(s, threads); !why.empty()) {
    result.error = why;
    return result;
  }
  result.image = Image(s.width, s.height);  // may throw std::bad_alloc: the caller says how large
  result.sample_counts.assign(size_t(s.width) * s.height, 0);

  // Within the limits, neither the tile counts nor their product overflow.
  const int tiles_x = s.width / kTile + (s.width % kTile != 0), tiles_y = s.height / kTile + (s.height % kTile != 0);
  const int tiles = tiles_x * tiles_y;
  std::atomic<int> next_tile{0}, done_tiles{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;  // guards result.work, result.error, nonfinite count and progress calls
  auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  auto worker = [&] {
    take_work_counters();
    uint64_t nonfinite = 0;
    try {
      for (int t; !failed && (t = next_tile++) < tiles;) {
        int x0 = (t % tiles_x) * kTile, y0 = (t / tiles_x) * kTile;
        for (int y = y0; y < std::min(y0 + kTile, s.height); ++y)
          for (int x = x0; x < std::min(x0 + kTile, s.width); ++x) {
            Rng rng = Rng::for_pixel(s.seed, x, y);
            PixelEstimate p = s.adaptive ? tracer.raytrace_pixel_adaptive(x, y, rng) : tracer.raytrace_pixel(x, y, rng);
            if (!is_finite(p.radiance)) {
              ++nonfinite;
              p.radiance = Spectrum(0.0);
            }
            size_t row = size_t(s.height - 1 - y);  // pixel y counts from the bottom
            result.image.pixels[row * s.width + x] = p.radiance;
            result.sample_counts[row * s.width + x] = p.num_samples;
          }
        int d = ++done_tiles;
        if (progress) {
          std::lock_guard<std::mutex> lock(mutex);
          progress(d, tiles, elapsed());
        }
      }
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(mutex);
      if (result.error.empty()) result.error = e.what();
      failed = true;
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (result.error.empty()) result.error = "unknown exception";
      failed = true;
    }
    std::lock_guard<std::mutex> lock(mutex);
    result.work += take_work_counters();
    result.nonfinite_pixels += nonfinite;
  };

  // Every worker, even with threads == 1, runs on a thread whose stack the
  // depth bound was measured for (render/limits.h), not on the caller's.
  std::string why;
  result.threads = run_on_threads(threads, kRenderThreadStackBytes, worker, &why);
  if (result.threads == 0) result.error = why;
  result.seconds = elapsed();
  return result;
}

}  // namespace pt
