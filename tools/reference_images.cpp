// pt-reference-images: renders the stored reference images of the scene
// library (scenes/library.json) with the reference solution.
//
//   pt-reference-images                       every scene, into scenes/reference/
//   pt-reference-images --only cornell_bunny  one scene
//   pt-reference-images --samples 256 --out /tmp/quick   a quick look (not for committing)
//   pt-reference-images --validate-only       redo only the validation (below) of the stored images
//
// Per scene it renders K = samples / pass_samples independent passes (pass k
// with seed `seed + k`, exactly `pathtracer-reference <scene> ... --seed
// <seed + k>`), and writes to the output folder:
//   <name>.exr      their average (float, ZIP)
//   <name>_sd.exr   the per-sample standard deviation per pixel (half, ZIP)
//   <name>.png      a preview
//   <name>.json     the sidecar: settings, seeds, render time, the commands,
//                   the git state of reference/, the error model's constants
//                   (support/error_model.h) and their validation: the first
//                   passes, kept in memory, are grouped into independent
//                   renders of 1, 4 and 16 passes and each is checked against
//                   the average of all the other passes, as the library test
//                   checks a render, so the sidecar shows the observed spread
//                   of relMSE and of the region z scores beside the model's.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "support/error_model.h"
#include "support/reference_check.h"
#include "support/reference_image.h"
#include "support/scene_library.h"
#include "pt_source_dir.h"

namespace fs = std::filesystem;
using nlohmann::ordered_json;
using namespace pt;

namespace {

std::string run(const std::string& cmd) {
  std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), &pclose);
  if (!p) return "";
  std::string out;
  char buf[256];
  while (fgets(buf, sizeof buf, p.get())) out += buf;
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

// What made the image: the commit, the last commit that changed the code the
// reference renders with, and any uncommitted change to it.
ordered_json git_state() {
  const std::string git = "git -C '" + std::string(PT_SOURCE_DIR) + "' ";
  ordered_json g;
  g["head"] = run(git + "rev-parse HEAD 2>/dev/null");
  g["reference_commit"] = run(git + "log -1 --format=%H -- reference skeleton 2>/dev/null");
  g["reference_tree"] = run(git + "rev-parse HEAD:reference 2>/dev/null");
  std::string dirty = run(git + "status --porcelain -- reference skeleton 2>/dev/null");
  std::vector<std::string> changed;
  std::istringstream lines(dirty);
  for (std::string line; std::getline(lines, line);) changed.push_back(line);
  g["uncommitted_changes"] = changed;
  return g;
}

std::string relative_to_repo(const std::string& path) {
  std::error_code ec;
  fs::path rel = fs::relative(path, PT_SOURCE_DIR, ec);
  return !ec && !rel.empty() && rel.begin()->string() != ".." ? rel.string() : path;
}

std::string format_seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  return buf;
}

Image as_float(const Image& img) {  // what write_exr stores
  Image out = img;
  for (Spectrum& p : out.pixels)
    for (int c = 0; c < 3; ++c) p[c] = double(float(p[c]));
  return out;
}

struct Summary {
  double n = 0, sum = 0, sum2 = 0, sum3 = 0, max = -1e300, max_abs = 0;
  void add(double x) {
    ++n, sum += x, sum2 += x * x, sum3 += x * x * x, max = std::max(max, x), max_abs = std::max(max_abs, std::abs(x));
  }
  double mean() const { return sum / n; }
  double sd() const { return n > 1 ? std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))) : 0.0; }
  double skewness() const {
    const double m = mean(), m2 = sum2 / n - m * m, m3 = sum3 / n - 3 * m * sum2 / n + 2 * m * m * m;
    return m2 > 0 ? m3 / std::pow(m2, 1.5) : 0.0;
  }
};

// Passes kept for the validation, as floats (half the memory of an Image).
using Pass = std::vector<float>;
Pass to_pass(const Image& img) {
  Pass p(img.pixels.size() * 3);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) p[3 * i + c] = float(img.pixels[i][c]);
  return p;
}

// Renders of g passes each, taken from the kept passes, checked against the
// average of every other pass: the library test's situation, repeated.
ordered_json validate(const std::vector<Pass>& kept, const Image& mean, const Image& sd,
                      const error_model::RelMSEModel& model, int total_passes, int n0, int g, double alpha) {
  const int groups = int(kept.size()) / g;
  if (groups < 2) return nullptr;
  Summary relmse, relmse_z, region_z;
  int relmse_failed = 0, region_failed = 0;
  library::ReferenceImage others;
  others.name = "leave-out";
  others.mean = Image(mean.width, mean.height);
  others.sd = sd;
  others.model = model;
  others.model.reference_samples = (total_passes - g) * n0;
  for (int j = 0; j < groups; ++j) {
    Image t(mean.width, mean.height);
    for (int k = j * g; k < (j + 1) * g; ++k)
      for (size_t i = 0; i < t.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) t.pixels[i][c] += kept[k][3 * i + c] / double(g);
    for (size_t i = 0; i < t.pixels.size(); ++i)
      others.mean.pixels[i] = (double(total_passes) * mean.pixels[i] - double(g) * t.pixels[i]) / double(total_passes - g);
    library::ReferenceCheck c = library::check_render(t, g * n0, others, alpha);
    relmse.add(c.relmse);
    relmse_z.add((c.relmse - c.expected) / c.sd);
    // A region of noise-free pixels (a black sky) differs by exactly 0: it
    // says nothing about the model and is left out of the z statistics.
    for (const auto& r : c.regions)
      if (r.mean_difference != 0.0) region_z.add(r.z);
    relmse_failed += !c.relmse_ok();
    region_failed += !c.regions_ok();
  }
  ordered_json v;
  v["spp"] = g * n0;
  v["renders"] = groups;
  v["relmse_mean"] = relmse.mean();
  v["relmse_sd"] = relmse.sd();
  v["model_expected"] = model.expected(g * n0);
  v["model_sd"] = model.sd(g * n0);
  v["relmse_z_max"] = relmse_z.max;
  v["relmse_z_skewness"] = relmse_z.skewness();
  v["relmse_failed"] = relmse_failed;
  v["region_z_count"] = region_z.n;
  v["region_z_mean"] = region_z.mean();
  v["region_z_sd"] = region_z.sd();
  v["region_z_max_abs"] = region_z.max_abs;
  v["region_failed"] = region_failed;
  return v;
}

// Renders passes first..first+count-1 of the scene, handing each to `take`.
template <class Take>
double render_passes(const library::LibraryScene& s, const Scene& scene, int count, int threads, Take take) {
  auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  double render_seconds = 0.0;
  for (int k = 0; k < count; ++k) {
    RenderResult r = library::render(s, scene, s.pass_samples, s.reference_seed + k, threads);
    if (!r.ok()) throw std::runtime_error(s.name + ": pass " + std::to_string(k) + ": " + r.error);
    if (r.nonfinite_pixels) throw std::runtime_error(s.name + ": pass " + std::to_string(k) + " has NaN pixels");
    render_seconds += r.seconds;
    take(k, r.image);
    if ((k + 1) % std::max(1, count / 20) == 0 || k + 1 == count)
      std::fprintf(stderr, "  %d/%d passes, %s, ETA %s\n", k + 1, count, format_seconds(elapsed()).c_str(),
                   format_seconds(elapsed() / (k + 1) * (count - k - 1)).c_str());
  }
  return render_seconds;
}

// The validation at 4, 16 and 64 spp (groups of 1, 4, 16 kept passes), printed and returned.
ordered_json validations(const std::vector<Pass>& kept, const Image& mean, const Image& sd,
                         const error_model::RelMSEModel& model, int passes, int n0) {
  ordered_json v = ordered_json::array();
  for (int g : {1, 4, 16}) {
    ordered_json one = validate(kept, mean, sd, model, passes, n0, g, 1e-5);
    if (one.is_null()) continue;
    std::fprintf(stderr,
                 "  validation at %d spp over %d renders: relMSE %.4g +- %.3g (model %.4g +- %.3g; max z %.2f, "
                 "skewness %.2f, %d failed); region z sd %.3f, max |z| %.2f (%d failed)\n",
                 one["spp"].get<int>(), one["renders"].get<int>(), one["relmse_mean"].get<double>(),
                 one["relmse_sd"].get<double>(), one["model_expected"].get<double>(), one["model_sd"].get<double>(),
                 one["relmse_z_max"].get<double>(), one["relmse_z_skewness"].get<double>(),
                 one["relmse_failed"].get<int>(), one["region_z_sd"].get<double>(),
                 one["region_z_max_abs"].get<double>(), one["region_failed"].get<int>());
    v.push_back(one);
  }
  return v;
}

LoadedScene load_announced(const library::LibraryScene& s, int samples, int threads, const char* what) {
  std::fprintf(stderr, "%s: %s, %dx%d, %s %d spp in %d passes of %d, %d light samples, depth %d, rr %g, %d threads\n",
               s.name.c_str(), relative_to_repo(s.path).c_str(), s.width, s.height, what, samples,
               samples / s.pass_samples, s.pass_samples, s.light_samples, s.max_depth, s.rr, threads);
  LoadedScene loaded = library::load(s);
  for (const auto& w : loaded.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return loaded;
}

void render_scene(const library::LibraryScene& s, const std::string& out_dir, int samples, int threads, int keep,
                  const std::string& command) {
  const int n0 = s.pass_samples, passes = samples / n0;
  auto start = std::chrono::steady_clock::now();
  LoadedScene loaded = load_announced(s, samples, threads, "rendering");
  const double load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  error_model::PassMoments moments(s.width, s.height, n0);
  std::vector<Pass> kept;
  const double render_seconds = render_passes(s, loaded.scene, passes, threads, [&](int k, const Image& img) {
    moments.add(img);
    if (k < keep) kept.push_back(to_pass(img));
  });
  const Image mean = as_float(moments.mean()), sd = moments.sample_sd();
  const error_model::RelMSEModel model = moments.model(mean);

  fs::create_directories(out_dir);
  const library::ReferencePaths p = library::reference_paths(out_dir, s.name);
  write_exr(p.mean, mean);
  library::write_half_exr(p.sd, sd);
  write_png(p.preview, mean);

  ordered_json j;
  j["name"] = s.name;
  j["purpose"] = s.purpose;
  j["scene"] = relative_to_repo(s.path);
  if (!s.generated.empty()) j["generated_by"] = s.generated;
  j["settings"] = {{"width", s.width},          {"height", s.height},      {"samples", samples},
                   {"pass_samples", n0},        {"passes", passes},        {"light_samples", s.light_samples},
                   {"max_depth", s.max_depth},  {"rr", s.rr},              {"seed", s.reference_seed},
                   {"seeds", "pass k (0 to passes - 1) uses seed + k"}};
  j["command"] = command;
  library::LibraryScene from_root = s;  // the command as run from the repository's root
  from_root.path = relative_to_repo(s.path);
  j["pass_command"] = from_root.command(n0, s.reference_seed, "pass.png") + "   # pass 0; pass k: --seed " +
                      std::to_string(s.reference_seed) + " + k; the stored mean is the average of the passes' EXRs";
  j["render_seconds"] = render_seconds;
  j["load_seconds"] = load_seconds;
  j["threads"] = threads;
  std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  j["date"] = date;
  j["git"] = git_state();
  ordered_json e;
  e["epsilon"] = error_model::kRelMSEEpsilon;
  e["reference_samples"] = model.reference_samples;
  e["a"] = model.a;
  e["c2"] = model.c2;
  e["c3"] = model.c3;
  for (int n : {4, 16, 64}) {
    e["expected_relmse"][std::to_string(n)] = model.expected(n);
    e["sd_relmse"][std::to_string(n)] = model.sd(n);
    e["reference_share"][std::to_string(n)] = model.reference_share(n);
  }
  j["error_model"] = e;
  std::fprintf(stderr, "  wrote %s (%ju bytes), %s (%ju), %s, %s; a = %.4g, expected relMSE at 16 spp %.4g\n",
               p.mean.c_str(), uintmax_t(fs::file_size(p.mean)), p.sd.c_str(), uintmax_t(fs::file_size(p.sd)),
               p.preview.c_str(), p.sidecar.c_str(), model.a, model.expected(16));
  j["validation"] = validations(kept, mean, sd, model, passes, n0);
  std::ofstream(p.sidecar) << j.dump(2) << "\n";
}

// Re-renders only the first `keep` passes (the same seeds give the same
// passes) and redoes the validation against the stored images and model:
// after a change to the check or the model, without re-rendering everything.
void revalidate_scene(const library::LibraryScene& s, const std::string& out_dir, int threads, int keep,
                      const std::string& command) {
  const library::ReferencePaths p = library::reference_paths(out_dir, s.name);
  std::ifstream in(p.sidecar);
  if (!in) throw std::runtime_error(p.sidecar + ": cannot open");
  ordered_json j = ordered_json::parse(in);
  const int passes = j.at("settings").at("passes").get<int>();
  keep = std::min(keep, passes - 16);  // a leave-out reference needs passes beyond the kept ones
  const library::ReferenceImage ref = library::read_reference(out_dir, s.name);
  LoadedScene loaded = load_announced(s, keep * s.pass_samples, threads, "validating on");
  std::vector<Pass> kept;
  render_passes(s, loaded.scene, keep, threads, [&](int, const Image& img) { kept.push_back(to_pass(img)); });
  j["validation"] = validations(kept, ref.mean, ref.sd, ref.model, passes, s.pass_samples);
  j["validation_command"] = command;
  std::ofstream(p.sidecar) << j.dump(2) << "\n";
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Renders the reference images of the scene library with the reference solution."};
  std::string manifest = library::default_manifest(), generated = PT_GENERATED_SCENES_DIR, out;
  std::vector<std::string> only;
  int threads = 2, samples = 0, keep = 512;
  app.add_option("--manifest", manifest, "The library manifest")->check(CLI::ExistingFile);
  app.add_option("--generated-dir", generated, "Where the build wrote the generated scenes");
  app.add_option("--out", out, "Output folder (default: the library's reference/ folder)");
  app.add_option("--only", only, "Render only these scenes (names from the manifest)");
  app.add_option("-t,--threads", threads, "Render threads")->check(CLI::Range(1, 256));
  app.add_option("--samples", samples, "Override the manifest's sample count (a quick look; do not commit)")
      ->check(CLI::PositiveNumber);
  app.add_option("--validation-passes", keep, "Passes kept in memory to validate the error model")
      ->check(CLI::Range(0, 4096));
  bool validate_only = false;
  app.add_flag("--validate-only", validate_only,
               "Keep the stored images; re-render only the validation passes and rewrite the sidecars' validation");
  CLI11_PARSE(app, argc, argv);

  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(i ? argv[i] : "pt-reference-images");
  try {
    library::Library lib = library::load_library(manifest, generated);
    if (out.empty()) out = lib.reference_dir;
    for (const std::string& name : only) lib.find(name);  // unknown names fail before any render
    for (const auto& s : lib.scenes) {
      if (!only.empty() && std::find(only.begin(), only.end(), s.name) == only.end()) continue;
      if (validate_only) {
        revalidate_scene(s, out, threads, keep, command);
        continue;
      }
      int n = samples > 0 ? samples : s.reference_samples;
      n = std::max(2 * s.pass_samples, n / s.pass_samples * s.pass_samples);
      render_scene(s, out, n, threads, keep, command);
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
