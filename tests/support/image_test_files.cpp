#include "support/image_test_files.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "io/image_file.h"

namespace pt::image_test {

namespace {

// The test images are small: each pixel drawn as a block, to the stored size.
Image enlarged(const Image& img, int factor) {
  Image out(img.width * factor, img.height * factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) out.at(x, y) = img.at(x / factor, y / factor);
  return out;
}

std::string& failure_image_dir() {
  static std::string dir;
  return dir;
}

}  // namespace

void set_failure_image_dir(const std::string& dir) { failure_image_dir() = dir; }

Image p_value_image(const Result& r) {
  Image img(r.width, r.height);
  std::vector<double> p(size_t(r.width) * r.height, 1.0);
  const int finest = *std::max_element(std::begin(kGrids), std::end(kGrids));
  for (const Region& g : r.regions)
    if (g.grid == finest)
      for (int y = g.y0; y < g.y1; ++y)
      for (int x = g.x0; x < g.x1; ++x) p[size_t(y) * r.width + x] = std::min(p[size_t(y) * r.width + x], g.p);
  const double top = -std::log10(r.alpha_each);
  for (size_t i = 0; i < p.size(); ++i)
    img.pixels[i] = p[i] < r.alpha_each ? Spectrum(1, 0, 0)
                                         : Spectrum(std::clamp(-std::log10(std::max(p[i], 1e-300)) / top, 0.0, 1.0));
  return img;
}

std::string write_failure_images(const Result& r) {
  if (r.render.pixels.empty() || r.reference.pixels.empty()) return "";
  namespace fs = std::filesystem;
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : r.spec.scene;
  const char* env = std::getenv("PT_IMAGE_TEST_DIR");
  fs::path dir = !failure_image_dir().empty() ? failure_image_dir() : env && *env ? env : "image_test_failures";
  try {
    // Absolute, so that a student can open it from the message wherever ctest ran the binary.
    dir = fs::absolute(dir).lexically_normal() / name;
    fs::create_directories(dir);
    const int factor = std::max(1, 256 / r.width);
    write_png((dir / "render.png").string(), enlarged(r.render, factor));
    write_png((dir / "reference.png").string(), enlarged(r.reference, factor));
    write_exr((dir / "render.exr").string(), r.render);
    write_exr((dir / "reference.exr").string(), r.reference);
    write_png((dir / "difference.png").string(), enlarged(difference_image(r.render, r.reference), factor));
    write_png((dir / "p_values.png").string(), enlarged(p_value_image(r), factor));
  } catch (const std::exception& e) {
    return "; no images written (" + std::string(e.what()) + ")";
  }
  return "; images in " + dir.string() +
         "/: render.png, reference.png (block-averaged to this size), difference.png (|illuminance difference|, "
         "false colour to its 99th percentile), p_values.png (the smallest p of each cell of the finest grid: black p = 1, "
         "white at the threshold, red below it)";
}

}  // namespace pt::image_test
