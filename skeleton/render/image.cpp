#include "render/image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <stb_image_write.h>
#include <tinyexr.h>

namespace pt {

void write_exr(const std::string& path, const Image& image) {
  std::vector<float> rgb(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = float(image.pixels[i][c]);
  const char* err = nullptr;
  if (SaveEXR(rgb.data(), image.width, image.height, 3, /*save_as_fp16=*/0, path.c_str(), &err) != TINYEXR_SUCCESS) {
    std::string msg = err ? err : "unknown error";
    FreeEXRErrorMessage(err);
    throw std::runtime_error(path + ": cannot write EXR: " + msg);
  }
}

Image read_exr(const std::string& path) {
  float* rgba = nullptr;
  int w = 0, h = 0;
  const char* err = nullptr;
  if (LoadEXR(&rgba, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
    std::string msg = err ? err : "unknown error";
    FreeEXRErrorMessage(err);
    throw std::runtime_error(path + ": cannot read EXR: " + msg);
  }
  Image img(w, h);
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = Spectrum(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);
  free(rgba);
  return img;
}

static double srgb_encode(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

void write_png(const std::string& path, const Image& image, double exposure) {
  double scale = std::exp2(exposure);
  std::vector<unsigned char> bytes(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double v = image.pixels[i][c] * scale;
      bytes[3 * i + c] = (unsigned char)std::lround(255.0 * srgb_encode(std::isfinite(v) ? v : 0.0));
    }
  if (!stbi_write_png(path.c_str(), image.width, image.height, 3, bytes.data(), image.width * 3))
    throw std::runtime_error(path + ": cannot write PNG");
}

// A perceptually ordered blue-to-red ramp through cyan, green and yellow.
static Spectrum false_colour(double t) {
  static const Spectrum stops[] = {{0, 0, 0.5}, {0, 0.5, 1}, {0, 0.8, 0.3}, {1, 0.9, 0}, {0.9, 0, 0}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
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
  for (size_t i = 0; i < diff.size(); ++i) diff[i] = std::abs(illuminance(test.pixels[i]) - illuminance(ref.pixels[i]));
  if (scale <= 0.0 && !diff.empty()) {
    std::vector<double> sorted = diff;
    auto k = sorted.begin() + (sorted.size() * 99) / 100;
    std::nth_element(sorted.begin(), k, sorted.end());
    scale = *k > 0.0 ? *k : 1.0;
  }
  Image img(ref.width, ref.height);
  for (size_t i = 0; i < diff.size(); ++i) img.pixels[i] = false_colour(diff[i] / scale);
  return img;
}

}  // namespace pt
