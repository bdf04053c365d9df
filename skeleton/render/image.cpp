#include "render/image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace pt {

static Spectrum false_colour(double t) {
  static const Spectrum stops[] = {{0, 0, 0.5}, {0, 0.5, 1}, {0, 0.8, 0.3}, {1, 0.9, 0}, {0.9, 0, 0}};
  t = (std::isnan(t) ? 1.0 : std::clamp(t, 0.0, 1.0)) * 4.0;  // NaN: the top
  int i = std::min(int(t), 3);
  return glm::mix(stops[i], stops[i + 1], t - i);
}

Image sample_rate_image(const std::vector<int>& counts, int width, int height, int max_samples) {
  Image img(width, height);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    img.pixels[i] = false_colour(max_samples > 0 ? double(counts[i]) / max_samples : 0.0);
  return img;
}

ImageError compare_images(const Image& test, const Image& ref) {
  if (test.width != ref.width || test.height != ref.height) throw std::invalid_argument("compare_images: sizes differ");
  double se = 0.0, rel = 0.0;
  for (size_t i = 0; i < ref.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double d = test.pixels[i][c] - ref.pixels[i][c];
      se += d * d;
      rel += d * d / (ref.pixels[i][c] * ref.pixels[i][c] + 1e-2);
    }
  double n = 3.0 * double(ref.pixels.size());
  return {std::sqrt(se / n), rel / n};
}

Image difference_image(const Image& test, const Image& ref, double scale) {
  if (test.width != ref.width || test.height != ref.height) throw std::invalid_argument("difference_image: sizes differ");
  std::vector<double> diff(ref.pixels.size());
  // NaN (a NaN pixel) counts as infinitely wrong: it shows red, and keeps
  // the ordering nth_element needs.
  for (size_t i = 0; i < diff.size(); ++i) {
    diff[i] = std::abs(illuminance(test.pixels[i]) - illuminance(ref.pixels[i]));
    if (std::isnan(diff[i])) diff[i] = INFINITY;
  }
  if (scale <= 0.0 && !diff.empty()) {
    std::vector<double> sorted = diff;
    auto k = sorted.begin() + (sorted.size() * 99) / 100;
    std::nth_element(sorted.begin(), k, sorted.end());
    scale = *k > 0.0 && std::isfinite(*k) ? *k : 1.0;
  }
  Image img(ref.width, ref.height);
  for (size_t i = 0; i < diff.size(); ++i) img.pixels[i] = false_colour(diff[i] / scale);
  return img;
}

}  // namespace pt
