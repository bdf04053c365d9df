#pragma once
#include <string>
#include <vector>

#include "core/vec.h"

namespace pt {

// A linear HDR RGB image; row 0 is the top row, as in image files.
struct Image {
  int width = 0, height = 0;
  std::vector<Spectrum> pixels;

  Image() = default;
  Image(int w, int h, const Spectrum& fill = Spectrum(0.0)) : width(w), height(h), pixels(size_t(w) * h, fill) {}
  Spectrum& at(int x, int y) { return pixels[size_t(y) * width + x]; }
  const Spectrum& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

// Blue (few samples) to red (the cap) map of samples per pixel, the course's
// "sample rate" image.
Image sample_rate_image(const std::vector<int>& counts, int width, int height, int max_samples);

// Differences against a reference of the same size.
struct ImageError {
  double rmse = 0.0;    // root mean squared error over all channels
  double relmse = 0.0;  // mean of (a - b)^2 / (b^2 + 1e-2), robust to dark pixels
};
ImageError compare_images(const Image& test, const Image& reference);
// Per-pixel |test - reference| illuminance on a false-colour scale whose top is
// `scale` (0 picks the 99th percentile).
Image difference_image(const Image& test, const Image& reference, double scale = 0.0);

}  // namespace pt
