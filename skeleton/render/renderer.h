#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/stats.h"
#include "render/image.h"
#include "render/pathtracer.h"

namespace pt {

struct RenderResult {
  Image image;                     // linear radiance, row 0 at the top
  std::vector<int> sample_counts;  // samples taken per pixel, same layout
  WorkCounters work;               // summed over threads
  double seconds = 0.0;
  uint64_t nonfinite_pixels = 0;   // NaN/Inf estimates, written as black and reported
  int threads = 0;                 // threads that rendered: fewer than asked when the system refused some
  std::string error;               // a task's exception ends the render; its message is kept here
  bool ok() const { return error.empty(); }
};

// Called from one thread as tiles finish: (tiles done, tiles total, seconds so far).
using ProgressFn = std::function<void(int, int, double)>;

// Renders tile by tile on `threads` worker threads. Each pixel draws from its
// own Rng (seed, x, y), so the image is independent of threads and tile order.
// Settings or a thread count beyond render/limits.h are refused (error set,
// nothing rendered); std::bad_alloc escapes when the image does not fit.
RenderResult render(const PathTracer& tracer, int threads, const ProgressFn& progress = {});

}  // namespace pt
