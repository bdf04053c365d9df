// pt-library-check: the grader's trusted half of the report's renders
// (autograder/report/report_renders.h). The renderer under test only writes an
// EXR; this tool, built by the instructor and shipped compiled in the grading
// kit, decides what the EXR shows.
//
//   pt-library-check plan --library scenes/library.json --out DIR
//       prints a JSON array, one entry per stored library scene (generated
//       scenes need the build's generator and are left out): its name, what it
//       is for, its settings, and the `pathtracer` arguments that render it
//       at the library test's samples and seed into DIR/<name>.exr (and .png).
//   pt-library-check compare --library scenes/library.json --scene NAME
//       --render DIR/NAME.exr --samples N --out DIR
//       judges the render exactly as the library test does
//       (tests/support/reference_check.h: relMSE against the error model, and
//       region means), writes DIR/NAME_submission.png and
//       DIR/NAME_difference.png, and prints one JSON object.
// Exit status: 0 when it printed its answer (whatever the verdict), 2 when it
// could not (an unreadable render is an answer: "error").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "support/reference_check.h"
#include "support/reference_image.h"
#include "support/scene_library.h"

namespace fs = std::filesystem;
using nlohmann::ordered_json;
using namespace pt;

namespace {

std::string settings_text(const library::LibraryScene& s, int spp) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%dx%d, %d spp, %d light sample%s, depth %d, RR %g", s.width, s.height, spp,
                s.light_samples, s.light_samples == 1 ? "" : "s", s.max_depth, s.rr);
  return buf;
}

// Full scale of the difference image: twice the 99th percentile of the noise
// a correct n-spp render has (per-pixel sd of the reference's samples, as
// illuminance, times sqrt(1/n + 1/N)). A correct render's image is dim and
// even; an error beyond the noise saturates. A fixed scale, not the image's
// own percentile, so that images of different submissions compare.
double noise_scale(const library::ReferenceImage& ref, int n) {
  std::vector<double> sd(ref.sd.pixels.size());
  for (size_t i = 0; i < sd.size(); ++i) sd[i] = illuminance(ref.sd.pixels[i]);
  if (sd.empty()) return 1.0;
  auto k = sd.begin() + (sd.size() * 99) / 100;
  std::nth_element(sd.begin(), k, sd.end());
  const double s = 2.0 * *k * std::sqrt(1.0 / n + 1.0 / std::max(1, ref.model.reference_samples));
  return s > 0.0 && std::isfinite(s) ? s : 1.0;
}

int plan(const std::string& manifest, const std::string& out) {
  const library::Library lib = library::load_library(manifest, "");
  ordered_json list = ordered_json::array();
  for (const auto& s : lib.scenes) {
    if (!s.generated.empty()) continue;
    // `-f` names the PNG; the renderer writes the EXR beside it.
    const std::string png = (fs::path(out) / (s.name + ".png")).string();
    const std::string exr = (fs::path(out) / (s.name + ".exr")).string();
    list.push_back({{"name", s.name},
                    {"purpose", s.purpose},
                    {"settings", settings_text(s, s.check_samples)},
                    {"samples", s.check_samples},
                    {"seed", s.check_seed},
                    {"exr", exr},
                    {"arguments", s.arguments(s.check_samples, s.check_seed, png)}});
  }
  std::cout << list.dump(1) << "\n";
  return 0;
}

int compare(const std::string& manifest, const std::string& name, const std::string& render, int samples,
            const std::string& out, double alpha) {
  const library::Library lib = library::load_library(manifest, "");
  const library::LibraryScene& scene = lib.find(name);
  const library::ReferenceImage ref = library::read_reference(lib.reference_dir, scene.name);
  ordered_json j = {{"scene", name}, {"samples", samples}};
  Image test;
  try {
    test = read_exr(render);
    if (test.width != ref.mean.width || test.height != ref.mean.height)
      throw std::runtime_error(render + ": " + std::to_string(test.width) + "x" + std::to_string(test.height) +
                               ", the reference is " + std::to_string(ref.mean.width) + "x" +
                               std::to_string(ref.mean.height));
  } catch (const std::exception& e) {
    j["error"] = e.what();
    std::cout << j.dump(1) << "\n";
    return 0;
  }
  const library::ReferenceCheck c = library::check_render(test, samples, ref, alpha);
  const fs::path dir(out);
  const std::string submission_png = (dir / (name + "_submission.png")).string();
  const std::string difference_png = (dir / (name + "_difference.png")).string();
  const double scale = noise_scale(ref, samples);
  write_png(submission_png, test);
  write_png(difference_png, difference_image(test, ref.mean, scale));
  j["relmse"] = c.relmse;
  j["expected_relmse"] = c.expected;
  j["bound"] = c.bound;
  j["nonfinite_pixels"] = c.nonfinite;
  j["worst_region"] = c.worst().describe();
  j["passed"] = c.passed();
  j["explanation"] = c.describe();
  j["difference_scale"] = scale;
  j["submission_png"] = submission_png;
  j["reference_png"] = library::reference_paths(lib.reference_dir, name).preview;
  j["difference_png"] = difference_png;
  std::cout << j.dump(1) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The grader's check of a render of a library scene (see the comment at the top of library_check.cpp)."};
  app.require_subcommand(1);
  std::string manifest, out, scene, render;
  int samples = 16;
  // As the library test: a correct render is flagged with probability below
  // 1e-5 (reference_check.h says why that level).
  double alpha = 1e-5;
  CLI::App* plan_cmd = app.add_subcommand("plan", "The renders to make: one JSON entry per stored scene");
  plan_cmd->add_option("--library", manifest, "scenes/library.json")->required()->check(CLI::ExistingFile);
  plan_cmd->add_option("--out", out, "Where the renders will be written")->required();
  CLI::App* compare_cmd = app.add_subcommand("compare", "Judge one render against its stored reference image");
  compare_cmd->add_option("--library", manifest, "scenes/library.json")->required()->check(CLI::ExistingFile);
  compare_cmd->add_option("--scene", scene, "Library scene name")->required();
  compare_cmd->add_option("--render", render, "The render (linear EXR)")->required();
  compare_cmd->add_option("--samples", samples, "Its samples per pixel")->required()->check(CLI::Range(1, 1 << 20));
  compare_cmd->add_option("--out", out, "Where the PNGs go")->required()->check(CLI::ExistingDirectory);
  compare_cmd->add_option("--alpha", alpha, "False-alarm probability of a correct render")->check(CLI::Range(1e-12, 0.5));
  CLI11_PARSE(app, argc, argv);
  try {
    if (*plan_cmd) return plan(manifest, out);
    return compare(manifest, scene, render, samples, out, alpha);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-library-check: %s\n", e.what());
    return 2;
  }
}
