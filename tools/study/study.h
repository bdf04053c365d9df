#pragma once
// pt-study: speed against accuracy for the methods of the five parts
// (README.md beside this file). Shared by the experiments: options, the
// table every experiment writes as CSV, the converged references cached in
// the output folder, and relMSE over independent seeds.
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "render/image.h"
#include "render/renderer.h"
#include "render/settings.h"
#include "support/scene_library.h"

namespace pt::study {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Options {
  bool quick = false;
  std::string out;           // the output folder (references cached in out/references)
  int threads = 2;           // render threads
  int seeds = 6;             // independent renders per configuration (relMSE's standard error)
  int width = 128, height = 96;  // every render of the study (library scenes at a quarter of their pixels)
  std::string command;       // as typed, for the page
};

// A CSV: a header and rows of cells, numbers written with 6 significant digits
// ("nan" where a column does not apply to a row).
class Table {
 public:
  explicit Table(std::vector<std::string> columns) : columns_(std::move(columns)) {}
  // A new row; set its cells with set(). Unset cells are written "nan".
  Table& row();
  Table& set(const std::string& column, double v);
  Table& set(const std::string& column, const std::string& v);
  size_t rows() const { return rows_.size(); }
  void write(const std::string& path) const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::map<std::string, std::string>> rows_;
};

// The columns every experiment's CSV starts with (the list).
std::vector<std::string> core_columns(std::vector<std::string> extra = {});

// A figure for the page: an image file in the output folder and its caption.
struct Picture {
  std::string file, caption;
};

// What an experiment hands to the page and the handouts.
struct Experiment {
  std::string name;      // file stem: <name>.csv, <name>.gp, <name>.png, <name>.svg
  std::string title;
  std::string scene;     // which scenes, with the settings
  std::string gnuplot;   // the script's body (terminal and output are added around it)
  std::string html;      // a paragraph: what the chart shows, with the measured figures
  std::vector<Picture> strip;                 // the equal-time images, in order
  std::vector<std::pair<std::string, std::string>> headline;  // name, value (with its error bar) for the docs
  double seconds = 0.0;  // wall time the experiment took
};

// --- Scenes and references -----------------------------------------------------
// A library scene loaded once (BVH built), rendered at the study's resolution.
struct StudyScene {
  library::LibraryScene entry;
  LoadedScene loaded;
  // The scene's library settings at the study's resolution, `spp` and `seed`.
  RenderSettings settings(const Options& opt, int spp = 1, uint64_t seed = 1) const;
};
StudyScene load_study_scene(const std::string& name);

// A converged image made by the same code at `spp` samples per pixel, in
// `passes` independent passes (seeds 1,000,000 + k, never a test seed), cached
// in out/references/<key>.exr with a sidecar <key>.json and reused when the
// sidecar's settings match.
struct Reference {
  std::string key;
  Image image;
  int spp = 0;
  // The reference's own contribution to the expected relMSE of a render
  // compared with it: a_ref / N, with a_ref the relative variance of one of
  // its samples (error_model.h, PassMoments, from the passes' spread).
  double own_relmse = 0.0;
  double energy = 0.0;     // sum of the pixels' illuminance
  double energy_se = 0.0;  // its standard error, from the passes
  double seconds = 0.0;    // render time when it was made
  bool cached = false;
};
Reference get_reference(const Options& opt, const StudyScene& s, RenderSettings settings, int spp);

// --- Measurements ----------------------------------------------------------------
double image_energy(const Image& img);

// `seeds` independent renders (seeds 1..seeds) of one configuration.
struct Measurement {
  int spp = 0, seeds = 0;
  double seconds = 0.0, seconds_se = 0.0;  // wall time of one render (mean and standard error)
  double rays = 0.0;                       // rays traced per render (mean)
  double samples = 0.0;                    // camera samples per pixel actually taken (mean; adaptive stops early)
  double relmse = kNaN, relmse_se = kNaN;  // against the reference, its own share subtracted
  double energy_bias = kNaN, energy_bias_se = kNaN;  // sum illuminance / reference's - 1
  Image first;                             // the seed-1 render (for strips)
  std::vector<int> first_counts;           // its samples per pixel
};
// Renders `settings` with seeds 1..opt.seeds (settings.seed is replaced) and
// compares each with `ref` (when given).
Measurement measure(const Options& opt, const StudyScene& s, RenderSettings settings, const Reference* ref);
// The core columns of a row from a measurement.
void set_row(Table& t, const std::string& method, const std::string& parameter, double value, const Measurement& m,
             const Reference* ref);

// --- Curves -----------------------------------------------------------------------
// Linear interpolation of log y against log x on points sorted by x; NaN
// outside [x_first, x_last].
double interp_loglog(const std::vector<double>& x, const std::vector<double>& y, double at);
// Same, linear in both.
double interp_linear(const std::vector<double>& x, const std::vector<double>& y, double at);

// --- Formatting ---------------------------------------------------------------------
std::string fmt(const char* f, double v);
std::string fmt2(const char* f, double a, double b);
// "3.4 ± 0.2" with the error bar's precision.
std::string pm(double v, double se, const char* unit = "");
// A PNG in the output folder: the image at exposure 0.
void write_picture(const Options& opt, const std::string& file, const Image& img);
double now_seconds();
// The 1-, 5- and 15-minute load averages, "4.16 5.61 6.38".
std::string load_average();

// The experiments, in the page's order.
Experiment run_bvh(const Options& opt);
Experiment run_direct(const Options& opt);
Experiment run_roulette(const Options& opt);
Experiment run_depth(const Options& opt);
Experiment run_adaptive(const Options& opt);
Experiment run_allocation(const Options& opt);
Experiment run_threads(const Options& opt);

}  // namespace pt::study
