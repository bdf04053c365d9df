#include "render/renderer.h"

#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>

namespace pt {

namespace {
constexpr int kTile = 16;
}

RenderResult render(const PathTracer& tracer, int threads, const ProgressFn& progress) {
  const RenderSettings& s = tracer.settings;
  RenderResult result;
  result.image = Image(s.width, s.height);
  result.sample_counts.assign(size_t(s.width) * s.height, 0);

  const int tiles_x = (s.width + kTile - 1) / kTile, tiles_y = (s.height + kTile - 1) / kTile;
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

  threads = std::max(1, threads);
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  result.seconds = elapsed();
  return result;
}

}  // namespace pt
