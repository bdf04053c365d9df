#include "app/cli.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "render/renderer.h"
#include "scene/course_camera.h"
#include "scene/scene_info.h"
#include "scene/scene_loader.h"

namespace pt {

namespace {

std::string format_duration(double s) {
  char buf[32];
  if (s < 10) std::snprintf(buf, sizeof buf, "%.2fs", s);
  else if (s < 60) std::snprintf(buf, sizeof buf, "%.1fs", s);
  else std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  return buf;
}

// Progress: one line rewritten in place on a terminal (at most 5 times a
// second); in a log, one line per 10%, so CI output stays readable.
void print_progress(int done, int total, double seconds) {
  static const bool tty = isatty(fileno(stderr));
  static double last_print = -1.0;
  static int last_decile = -1;
  const int decile = 10 * done / total;
  if (tty ? (seconds - last_print < 0.2 && done != total) : decile == last_decile) return;
  last_print = seconds;
  last_decile = decile;
  double eta = done > 0 ? seconds * (total - done) / done : 0.0;
  std::fprintf(stderr, "%s[%3d%%] %d/%d tiles, %s elapsed, ETA %s   %s", tty ? "\r" : "", 100 * done / total, done,
               total, format_duration(seconds).c_str(), format_duration(eta).c_str(), tty ? "" : "\n");
  if (tty && done == total) std::fprintf(stderr, "\n");
}

std::string stem_of(const std::string& path) {
  std::filesystem::path p(path);
  return (p.parent_path() / p.stem()).string();
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"Headless path tracer: renders SCENE to a PNG (tone-mapped) and an EXR (linear) beside it."};
  RenderSettings s;
  std::string scene_path, output = "render.png", camera_path;
  std::vector<int> resolution;
  std::vector<double> adaptive;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  int accumulate = 1;
  double exposure = 0.0;
  bool quiet = false, course_view = false, scene_info = false;

  app.add_option("scene", scene_path, "Scene file (.json or .dae)")->required();
  app.add_option("-s,--samples", s.ns_aa, "Samples per pixel (the cap with -a)")->check(CLI::PositiveNumber);
  app.add_option("-l,--light-samples", s.ns_area_light, "Samples per area light")->check(CLI::PositiveNumber);
  app.add_option("-m,--max-depth", s.max_ray_depth, "Maximum ray depth (bounces)")->check(CLI::NonNegativeNumber);
  app.add_option("-t,--threads", threads, "Render threads")->check(CLI::PositiveNumber);
  app.add_option("-f,--file", output, "Output PNG; the EXR is written beside it");
  app.add_option("-r,--resolution", resolution, "Image width and height")->expected(2)->check(CLI::PositiveNumber);
  app.add_option("-a,--adaptive", adaptive, "Adaptive sampling: samples per batch and max tolerance")->expected(2);
  app.add_flag("-H,--hemisphere", s.direct_hemisphere_sample, "Uniform hemisphere sampling for direct light");
  app.add_option("-o,--accumulate", accumulate, "1: sum all bounces; 0: only bounce number -m")
      ->check(CLI::IsMember({0, 1}));
  app.add_option("-c,--camera", camera_path, "Camera file replacing the scene's camera");
  app.add_option("--rr", s.rr_continue_prob, "Russian roulette continuation probability")
      ->check(CLI::Range(1e-3, 1.0));
  app.add_option("--seed", s.seed, "Render seed");
  app.add_option("--exposure", exposure, "PNG exposure in stops");
  app.add_flag("-q,--quiet", quiet, "No progress line");
  app.add_flag("--course-camera", course_view,
               "Frame the scene as the course's viewer does (its bounding box, the camera's view direction)");
  app.add_flag("--scene-info", scene_info, "Print a summary of the scene as one JSON object and exit");
  CLI11_PARSE(app, argc, argv);

  if (!resolution.empty()) s.width = resolution[0], s.height = resolution[1];
  if (!adaptive.empty()) {
    s.adaptive = true;
    s.samples_per_batch = std::max(1, int(adaptive[0]));
    s.max_tolerance = adaptive[1];
  }
  s.accumulate_bounces = accumulate != 0;

  LoadedScene loaded;
  try {
    loaded = load_scene(scene_path, scene_info ? BuildBvh::No : BuildBvh::Yes);
    if (!camera_path.empty()) loaded.scene.camera = load_camera(camera_path);
    Camera& camera = loaded.scene.camera;
    if (course_view) camera = course_camera(camera, loaded.scene.bounds(), s.width, s.height);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  Scene& scene = loaded.scene;
  scene.camera.set_aspect(double(s.width) / s.height);
  if (scene_info) {
    std::cout << scene_info_json(loaded) << std::endl;  // the warnings are in it
    return 0;
  }
  for (const auto& w : loaded.warnings) std::cerr << "warning: " << scene_path << ": " << w << "\n";

  std::fprintf(stderr, "%s: %zu primitives (%zu triangles), %zu lights; %dx%d, %d spp%s, %d light samples, depth %d, %d threads\n",
               scene_path.c_str(), scene.primitives.size(), scene.triangle_count(), scene.lights.size(), s.width,
               s.height, s.ns_aa, s.adaptive ? " (adaptive cap)" : "", s.ns_area_light, s.max_ray_depth, threads);
  PathTracer tracer(scene, s);
  RenderResult result = render(tracer, threads, quiet ? ProgressFn{} : ProgressFn(print_progress));
  if (!result.ok()) {
    std::cerr << "\nerror: render stopped: " << result.error << "\n";
    return 1;
  }

  try {
    write_png(output, result.image, exposure);
    write_exr(stem_of(output) + ".exr", result.image);
    if (s.adaptive) write_png(stem_of(output) + "_rate.png", sample_rate_image(result.sample_counts, s.width, s.height, s.ns_aa));
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }

  const WorkCounters& w = result.work;
  double rays = double(w.rays);
  std::fprintf(stderr, "wrote %s and %s.exr%s\n", output.c_str(), stem_of(output).c_str(),
               s.adaptive ? (" and " + stem_of(output) + "_rate.png").c_str() : "");
  // Primitive tests are counted by the framework for every BVH; node visits
  // only by a BVH that counts them itself (the reference does).
  char nodes[64] = "node visits not counted by this BVH";
  if (w.node_visits > 0) std::snprintf(nodes, sizeof nodes, "%.1f node visits/ray", w.node_visits / rays);
  std::fprintf(stderr, "rays traced: %llu  |  %.2f Mrays/s  |  %.1f intersection tests/ray  |  %s  |  time %s\n",
               (unsigned long long)w.rays, rays / std::max(result.seconds, 1e-9) / 1e6,
               rays > 0 ? w.primitive_tests / rays : 0.0, nodes, format_duration(result.seconds).c_str());
  if (s.adaptive) {
    double total = 0;
    for (int c : result.sample_counts) total += c;
    std::fprintf(stderr, "adaptive: %.1f samples per pixel on average (cap %d)\n", total / result.sample_counts.size(), s.ns_aa);
  }
  if (result.nonfinite_pixels > 0)
    std::fprintf(stderr, "warning: %llu pixels had NaN or infinite radiance and were written as black\n",
                 (unsigned long long)result.nonfinite_pixels);
  return 0;
}

}  // namespace pt
