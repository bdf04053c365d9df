#include "render/tiles.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <string>

#include "render/limits.h"
#include "render/worker_threads.h"

namespace pt {

void for_each_pixel(int width, int height, int threads, const std::function<bool(int, int, size_t)>& pixel,
                    const std::function<void(int, int)>& tile_done, RenderResult& result, int tile) {
  const int kTile = std::max(1, tile);
  // Within the limits, neither the tile counts nor their product overflow.
  const int tiles_x = width / kTile + (width % kTile != 0), tiles_y = height / kTile + (height % kTile != 0);
  const int tiles = tiles_x * tiles_y;
  std::atomic<int> next_tile{0}, done_tiles{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;  // guards result.work, result.error, nonfinite count and tile_done calls

  auto worker = [&] {
    take_work_counters();
    uint64_t nonfinite = 0;
    try {
      for (int t; !failed && (t = next_tile++) < tiles;) {
        int x0 = (t % tiles_x) * kTile, y0 = (t / tiles_x) * kTile;
        for (int y = y0; y < std::min(y0 + kTile, height); ++y)
          for (int x = x0; x < std::min(x0 + kTile, width); ++x)
            if (!pixel(x, y, size_t(height - 1 - y) * width + x)) ++nonfinite;  // pixel y counts from the bottom
        int d = ++done_tiles;
        if (tile_done) {
          std::lock_guard<std::mutex> lock(mutex);
          tile_done(d, tiles);
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
  if (result.threads == 0 && result.error.empty()) result.error = why;
}

}  // namespace pt
