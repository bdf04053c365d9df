// pathtracer-compare: error of a render against a reference image.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/command_line.h"
#include "render/image.h"
#include "io/image_file.h"

namespace {

size_t count_nonfinite(const pt::Image& img) {
  size_t n = 0;
  for (const auto& p : img.pixels) n += !pt::is_finite(p);
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Compares a linear EXR render with a reference EXR: prints RMSE and relMSE, writes a false-colour "
               "difference image. Exit status: 0 within the thresholds given, 1 above one, 2 unusable input."};
  std::string test_path, ref_path, diff_path;
  double scale = 0.0, max_relmse = -1.0, max_rmse = -1.0;
  app.add_option("test", test_path, "Render to judge (.exr)")->required();
  app.add_option("reference", ref_path, "Reference render (.exr)")->required();
  app.add_option("-d,--diff", diff_path, "Write |test - reference| illuminance as a false-colour PNG");
  app.add_option("--scale", scale, "Difference that maps to red (default: the 99th percentile)")
      ->check(pt::within(0, 1e30));
  app.add_option("--max-relmse", max_relmse, "Exit 1 when relMSE is above this")->check(pt::within(0, 1e30));
  app.add_option("--max-rmse", max_rmse, "Exit 1 when RMSE is above this")->check(pt::within(0, 1e30));
  if (auto status = pt::parse_command_line(app, argc, argv)) return *status;

  try {
    pt::Image test = pt::read_exr(test_path), ref = pt::read_exr(ref_path);
    if (test.width != ref.width || test.height != ref.height) {
      std::cerr << "error: " << test_path << " is " << test.width << "x" << test.height << " but " << ref_path
                << " is " << ref.width << "x" << ref.height << "\n";
      return pt::kExitBadInput;
    }
    if (size_t n = count_nonfinite(ref)) {
      std::cerr << "error: " << ref_path << ": NaN or infinite pixels: " << n << " (not a usable reference)\n";
      return pt::kExitBadInput;
    }
    pt::ImageError e = pt::compare_images(test, ref);
    std::printf("RMSE %.6g  relMSE %.6g\n", e.rmse, e.relmse);
    const size_t nonfinite = count_nonfinite(test);
    if (nonfinite) std::printf("%s: NaN or infinite pixels: %zu\n", test_path.c_str(), nonfinite);
    if (!diff_path.empty()) {
      pt::write_png(diff_path, pt::difference_image(test, ref, scale));
      std::printf("wrote %s\n", diff_path.c_str());
    }
    // A NaN error (from NaN pixels) fails every threshold.
    struct Threshold {
      const char *metric, *option;
      double value, bound;
    };
    bool failed = false;
    for (const Threshold& t : {Threshold{"relMSE", "--max-relmse", e.relmse, max_relmse},
                               Threshold{"RMSE", "--max-rmse", e.rmse, max_rmse}})
      if (t.bound >= 0 && !(t.value <= t.bound)) {
        std::printf("FAIL: %s %.6g is not within %s %.6g\n", t.metric, t.value, t.option, t.bound);
        failed = true;
      }
    return failed ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return pt::kExitBadInput;
  }
}
