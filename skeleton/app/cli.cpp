#include "app/cli.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <thread>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "app/command_line.h"
#include "app/part_origins.h"
#include "app/viewer_entry.h"
#include "app/viewer_server.h"
#include "render/limits.h"
#include "render/renderer.h"
#include "scene/course_camera.h"
#include "io/image_file.h"
#include "io/scene_info.h"
#include "io/scene_loader.h"

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

// Refuses, before anything is rendered, an output the writers could not
// create: a directory, a missing directory, no permission. (A full disk shows
// only when writing.) "" when the path looks writable.
std::string check_writable(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(path);
  if (fs::is_directory(p, ec)) return path + ": is a directory";
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  if (!fs::is_directory(dir, ec)) return path + ": the directory " + dir.string() + " does not exist";
  const bool exists = fs::exists(p, ec);
  if (access(exists ? p.c_str() : dir.c_str(), W_OK) != 0) return path + ": cannot write: " + std::strerror(errno);
  return "";
}

// -a BATCH TOLERANCE: "" when usable.
std::string check_adaptive(const std::vector<double>& a) {
  if (!(a[0] >= 1 && a[0] <= kMaxSamples && a[0] == std::floor(a[0])))
    return "--adaptive: the batch size " + format_bound(a[0]) + " is not an integer in [1, " +
           std::to_string(kMaxSamples) + "]";
  if (!(std::isfinite(a[1]) && a[1] >= 0))
    return "--adaptive: the tolerance " + format_bound(a[1]) + " is not a finite number >= 0";
  return "";
}

// A task left as a stub stops the render; say how to render meanwhile.
std::string with_stub_hint(const std::string& message) {
  const std::string hint = stub_hint(message);
  return hint.empty() ? message : message + "\n  " + hint;
}

int bad_input(const std::string& message) {
  std::cerr << "error: " << with_stub_hint(message) << "\n";
  return kExitBadInput;
}

}  // namespace

ViewerEntry& viewer_entry() {
  static ViewerEntry entry = nullptr;
  return entry;
}

int run_cli(int argc, char** argv, const char* student_parts, const char* chosen_by) {
  CLI::App app{"Headless path tracer: renders SCENE to a PNG (tone-mapped) and an EXR (linear) beside it."};
  RenderSettings s;
  std::string scene_path, output = "render.png", camera_path;
  std::vector<int> resolution;
  std::vector<double> adaptive;
  int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, kMaxThreads);
  int accumulate = 1;
  double exposure = 0.0;
  bool quiet = false, course_view = false, scene_info = false, view = false;
  int port = 8642;

  app.add_option("scene", scene_path, "Scene file (.json or .dae)")->required();
  app.add_option("-s,--samples", s.ns_aa, "Samples per pixel (the cap with -a)")->check(within(1, kMaxSamples));
  app.add_option("-l,--light-samples", s.ns_area_light, "Samples per area light")
      ->check(within(1, kMaxLightSamples));
  app.add_option("-m,--max-depth", s.max_ray_depth, "Maximum ray depth (bounces)")
      ->check(within(0, kMaxRayDepth, "the recursion's stack bound"));
  app.add_option("-t,--threads", threads, "Render threads")->check(within(1, kMaxThreads));
  app.add_option("-f,--file", output, "Output PNG; the EXR is written beside it");
  app.add_option("-r,--resolution", resolution, "Image width and height")->expected(2)->check(within(1, kMaxImageSide));
  app.add_option("-a,--adaptive", adaptive, "Adaptive sampling: samples per batch and max tolerance")->expected(2);
  app.add_option("--adaptive-budget", s.adaptive_budget,
                 "Budgeted adaptive sampling: this many samples per pixel on average, each pixel's share in "
                 "proportion to its relative noise (a pilot pass estimates it); not with -a")
      ->check(within(kMinAdaptiveBudget, kMaxSamples, "the pilot needs two samples"));
  app.add_option("--adaptive-rounds", s.adaptive_rounds,
                 "With --adaptive-budget: spend the budget in this many rounds, re-estimating each pixel's noise "
                 "from its neighbours' samples before each")
      ->check(within(1, kMaxAdaptiveRounds));
  app.add_flag("-H,--hemisphere", s.direct_hemisphere_sample, "Uniform hemisphere sampling for direct light");
  app.add_option("-o,--accumulate", accumulate, "1: sum all bounces; 0: only bounce number -m")
      ->check(CLI::IsMember({0, 1}));
  app.add_option("-c,--camera", camera_path, "Camera file replacing the scene's camera");
  app.add_option("--rr", s.rr_continue_prob, "Russian roulette continuation probability")->check(within(1e-3, 1.0));
  app.add_option("--seed", s.seed, "Render seed")->check(unsigned_integer());
  app.add_option("--exposure", exposure, "PNG exposure in stops")->check(within(-64, 64));
  app.add_flag("-q,--quiet", quiet, "No progress line");
  app.add_flag("--course-camera", course_view,
               "Frame the scene as the course's viewer does (its bounding box, the camera's view direction)");
  app.add_flag("--scene-info", scene_info, "Print a summary of the scene as one JSON object and exit");
  app.add_flag("--view", view,
               "Serve the interactive viewer on 127.0.0.1 (prints its URL): progressive render, camera, BVH walk, "
               "pixel inspector, reference flip; the other flags are its starting settings");
  app.add_option("--port", port, "The viewer's port (0: any free port)")->check(within(0, 65535));
  if (auto status = parse_command_line(app, argc, argv)) return *status;

  if (!resolution.empty()) s.width = resolution[0], s.height = resolution[1];
  if (!adaptive.empty()) {
    if (std::string why = check_adaptive(adaptive); !why.empty()) return bad_input(why);
    s.adaptive = true;
    s.samples_per_batch = int(adaptive[0]);
    s.max_tolerance = adaptive[1];
  }
  s.accumulate_bounces = accumulate != 0;
  if (s.adaptive && s.adaptive_budget > 0) return bad_input("--adaptive-budget and -a are two different samplers: choose one");
  if (app.count("--adaptive-rounds") > 0 && s.adaptive_budget == 0)
    return bad_input("--adaptive-rounds is for --adaptive-budget");
  // What the options cannot check one by one (the pixel count).
  if (std::string why = check_render_limits(s, threads); !why.empty()) return bad_input(why);

  const std::string exr_path = stem_of(output) + ".exr", rate_path = stem_of(output) + "_rate.png";
  if (exr_path == output) return bad_input("-f names the PNG and the EXR goes beside it: -f " + stem_of(output) + ".png");
  std::vector<std::string> outputs = {output, exr_path};
  const bool rate_image = s.adaptive || s.adaptive_budget > 0;
  if (rate_image) outputs.push_back(rate_path);
  for (const std::string& path : outputs)
    if (std::string why = check_writable(path); !why.empty() && !scene_info && !view) return bad_input(why);

  // Before the scene: loading it builds the BVH, which is already part 2's code.
  if (student_parts && !scene_info) std::fprintf(stderr, "%s\n", part_origins(student_parts, chosen_by ? chosen_by : "").c_str());
  LoadedScene loaded;
  try {
    // The viewer builds the BVH itself, so that a student's construct_bvh
    // that throws shows on its page instead of ending it.
    loaded = load_scene(scene_path, scene_info || view ? BuildBvh::No : BuildBvh::Yes);
    if (!camera_path.empty()) loaded.scene.camera = load_camera(camera_path);
    if (view) {
      for (const auto& w : loaded.warnings) std::cerr << "warning: " << scene_path << ": " << w << "\n";
#ifdef PT_NO_VIEWER_LIBRARY
      return bad_input("--view: this build has no viewer: cpp-httplib was not found when it was configured (macOS: "
                       "brew install cpp-httplib; Debian or Ubuntu: apt install libcpp-httplib-dev; then configure again)");
#endif
      if (!viewer_entry()) return bad_input("--view: this build of the renderer has no viewer");
      ViewerOptions options{scene_path, {s, exposure}, threads, course_view, port, {}, ""};
      try {
        loaded.scene.build();
      } catch (const std::exception& e) {
        options.scene_error = std::string("building the BVH: ") + e.what();
        std::cerr << "error: " << scene_path << ": " << options.scene_error << " (the viewer shows the scene without it)\n";
      }
      return viewer_entry()(loaded.scene, options);
    }
    Camera& camera = loaded.scene.camera;
    if (course_view) camera = course_camera(camera, loaded.scene.bounds(), s.width, s.height);
  } catch (const std::exception& e) {
    return bad_input(e.what());
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
               s.height, s.adaptive_budget > 0 ? s.adaptive_budget : s.ns_aa,
               s.adaptive ? " (adaptive cap)" : s.adaptive_budget > 0 ? " on average (adaptive budget; -s unused)" : "",
               s.ns_area_light, s.max_ray_depth, threads);
  PathTracer tracer(scene, s);
  RenderResult result;
  try {
    result = render(tracer, threads, quiet ? ProgressFn{} : ProgressFn(print_progress));
  } catch (const std::bad_alloc&) {
    return bad_input("out of memory for a " + std::to_string(s.width) + "x" + std::to_string(s.height) + " image");
  }
  if (result.threads > 0 && result.threads < threads)
    std::fprintf(stderr, "warning: the system started only %d of the %d render threads asked for\n", result.threads,
                 threads);
  if (!result.ok()) {
    std::cerr << "\nerror: render stopped: " << with_stub_hint(result.error) << "\n";
    return 1;
  }

  // The rate image's red: the cap with -a, the largest count with a budget.
  const auto& counts = result.sample_counts;
  const int rate_cap = s.adaptive || counts.empty() ? s.ns_aa : *std::max_element(counts.begin(), counts.end());
  // Stops at the first file that cannot be written (the message names it);
  // "wrote" only once all are.
  try {
    write_png(output, result.image, exposure);
    write_exr(exr_path, result.image);
    if (rate_image) write_png(rate_path, sample_rate_image(result.sample_counts, s.width, s.height, rate_cap));
  } catch (const std::exception& e) {
    return bad_input(e.what());
  }

  const WorkCounters& w = result.work;
  double rays = double(w.rays);
  std::fprintf(stderr, "wrote %s and %s%s\n", output.c_str(), exr_path.c_str(),
               rate_image ? (" and " + rate_path).c_str() : "");
  // Primitive tests are counted by the framework for every BVH; node visits
  // only by a BVH that counts them itself (the reference does).
  char nodes[64] = "node visits not counted by this BVH";
  if (w.node_visits > 0) std::snprintf(nodes, sizeof nodes, "%.1f node visits/ray", w.node_visits / rays);
  std::fprintf(stderr, "rays traced: %llu  |  %.2f Mrays/s  |  %.1f intersection tests/ray  |  %s  |  time %s\n",
               (unsigned long long)w.rays, rays / std::max(result.seconds, 1e-9) / 1e6,
               rays > 0 ? w.primitive_tests / rays : 0.0, nodes, format_duration(result.seconds).c_str());
  if (rate_image) {
    double total = 0;
    for (int c : result.sample_counts) total += c;
    if (s.adaptive)
      std::fprintf(stderr, "adaptive: %.1f samples per pixel on average (cap %d)\n", total / result.sample_counts.size(), s.ns_aa);
    else
      std::fprintf(stderr, "adaptive budget: %.1f samples per pixel on average, %d at most, %d at least\n",
                   total / result.sample_counts.size(), rate_cap,
                   *std::min_element(result.sample_counts.begin(), result.sample_counts.end()));
  }
  if (result.nonfinite_pixels > 0)
    std::fprintf(stderr, "warning: %llu pixels had NaN or infinite radiance and were written as black\n",
                 (unsigned long long)result.nonfinite_pixels);
  return 0;
}

}  // namespace pt
