#pragma once
// The tiled, multithreaded pixel loop shared by the fixed, adaptive and
// budgeted renders (renderer.cpp, budget.cpp).
#include <cstddef>
#include <functional>

#include "render/renderer.h"

namespace pt {

// Calls pixel(x, y, index) once for every pixel of a width x height image,
// tile by tile on `threads` worker threads; index = (height - 1 - y) * width
// + x (row 0 at the top). pixel returns false when its estimate was not
// finite (counted in result.nonfinite_pixels). tile_done(done, total) is
// called under a lock as tiles finish. The first exception ends the loop and
// its message goes to result.error; work counters and thread count are added
// to result.
// `tile` is the side of a tile in pixels: small tiles balance the threads
// when the work per pixel is very uneven (the budgeted sampler's counts).
void for_each_pixel(int width, int height, int threads, const std::function<bool(int, int, size_t)>& pixel,
                    const std::function<void(int, int)>& tile_done, RenderResult& result, int tile = 16);

}  // namespace pt
