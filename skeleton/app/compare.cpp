// pathtracer-compare: error of a render against a reference image.
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "render/image.h"

int main(int argc, char** argv) {
  CLI::App app{"Compares a linear EXR render with a reference EXR: prints RMSE and relMSE, writes a false-colour "
               "difference image."};
  std::string test_path, ref_path, diff_path;
  double scale = 0.0;
  app.add_option("test", test_path, "Render to judge (.exr)")->required()->check(CLI::ExistingFile);
  app.add_option("reference", ref_path, "Reference render (.exr)")->required()->check(CLI::ExistingFile);
  app.add_option("-d,--diff", diff_path, "Write |test - reference| illuminance as a false-colour PNG");
  app.add_option("--scale", scale, "Difference that maps to red (default: the 99th percentile)");
  CLI11_PARSE(app, argc, argv);
  try {
    pt::Image test = pt::read_exr(test_path), ref = pt::read_exr(ref_path);
    if (test.width != ref.width || test.height != ref.height) {
      std::cerr << "error: " << test_path << " is " << test.width << "x" << test.height << " but " << ref_path
                << " is " << ref.width << "x" << ref.height << "\n";
      return 2;
    }
    pt::ImageError e = pt::compare_images(test, ref);
    std::printf("RMSE %.6g  relMSE %.6g\n", e.rmse, e.relmse);
    if (!diff_path.empty()) {
      pt::write_png(diff_path, pt::difference_image(test, ref, scale));
      std::printf("wrote %s\n", diff_path.c_str());
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
