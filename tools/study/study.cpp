#include "study.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/image_file.h"
#include "render/pathtracer.h"
#include "support/error_model.h"

namespace fs = std::filesystem;

namespace pt::study {

// --- Table ------------------------------------------------------------------------
Table& Table::row() {
  rows_.emplace_back();
  return *this;
}
Table& Table::set(const std::string& column, double v) {
  return set(column, std::isfinite(v) ? fmt("%.6g", v) : std::string("nan"));
}
Table& Table::set(const std::string& column, const std::string& v) {
  if (std::find(columns_.begin(), columns_.end(), column) == columns_.end())
    throw std::logic_error("no column " + column);
  if (v.find_first_of(",\"\n") != std::string::npos) throw std::logic_error("cell needs quoting: " + v);
  rows_.back()[column] = v;
  return *this;
}
void Table::write(const std::string& path) const {
  // Rows grouped by method, in order of first appearance (stable), so that
  // gnuplot draws each method's points as one connected line.
  std::vector<std::string> methods;
  for (const auto& r : rows_) {
    auto it = r.find("method");
    const std::string m = it == r.end() ? "" : it->second;
    if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
  }
  std::vector<const std::map<std::string, std::string>*> sorted;
  for (const std::string& m : methods)
    for (const auto& r : rows_) {
      auto it = r.find("method");
      if ((it == r.end() ? "" : it->second) == m) sorted.push_back(&r);
    }
  std::ofstream f(path);
  for (size_t i = 0; i < columns_.size(); ++i) f << (i ? "," : "") << columns_[i];
  f << "\n";
  for (const auto* r : sorted) {
    for (size_t i = 0; i < columns_.size(); ++i) {
      auto it = r->find(columns_[i]);
      f << (i ? "," : "") << (it == r->end() ? "nan" : it->second);
    }
    f << "\n";
  }
  if (!f) throw std::runtime_error(path + ": cannot write");
}

std::vector<std::string> core_columns(std::vector<std::string> extra) {
  std::vector<std::string> c = {"method",  "parameter", "value",     "samples",        "rays",
                                "wall_seconds", "wall_seconds_se", "relmse", "relmse_se", "seeds",
                                "reference_spp"};
  c.insert(c.end(), extra.begin(), extra.end());
  return c;
}

// --- Scenes ------------------------------------------------------------------------
RenderSettings StudyScene::settings(const Options& opt, int spp, uint64_t seed) const {
  RenderSettings s = entry.settings(spp, seed);
  s.width = opt.width;
  s.height = opt.height;
  return s;
}

StudyScene load_study_scene(const std::string& name) {
  library::Library lib = library::load_library(library::default_manifest(), PT_GENERATED_SCENES_DIR);
  StudyScene s;
  s.entry = lib.find(name);
  s.loaded = library::load(s.entry);  // the camera's aspect is the library's 4:3, as the study's
  return s;
}

// --- References ----------------------------------------------------------------------
namespace {

std::string settings_key(const std::string& scene, const RenderSettings& s, int spp) {
  std::string k = scene + "_" + std::to_string(s.width) + "x" + std::to_string(s.height) + "_m" +
                  std::to_string(s.max_ray_depth) + "_l" + std::to_string(s.ns_area_light) + "_rr" +
                  fmt("%g", s.rr_continue_prob) + (s.direct_hemisphere_sample ? "_H" : "") + "_s" + std::to_string(spp);
  return k;
}

}  // namespace

double image_energy(const Image& img) {
  double e = 0.0;
  for (const Spectrum& p : img.pixels) e += illuminance(p);
  return e;
}

Reference get_reference(const Options& opt, const StudyScene& s, RenderSettings settings, int spp) {
  settings.adaptive = false;
  settings.accumulate_bounces = true;
  const int passes = 32;  // enough for the reference's own variance to a few percent
  if (spp % passes != 0 || spp / passes < 2) throw std::logic_error("reference spp must be a multiple of 32 passes of 2 or more");
  Reference ref;
  ref.key = settings_key(s.entry.name, settings, spp);
  ref.spp = spp;
  const fs::path dir = fs::path(opt.out) / "references";
  fs::create_directories(dir);
  const fs::path exr = dir / (ref.key + ".exr"), sidecar = dir / (ref.key + ".json");
  if (fs::exists(exr) && fs::exists(sidecar)) {
    try {
      nlohmann::json j = nlohmann::json::parse(std::ifstream(sidecar));
      if (j.at("key") == ref.key && j.at("spp") == spp) {
        ref.image = read_exr(exr.string());
        ref.own_relmse = j.at("own_relmse");
        ref.energy = j.at("energy");
        ref.energy_se = j.at("energy_se");
        ref.seconds = j.at("seconds");
        ref.cached = true;
        if (ref.image.width == settings.width && ref.image.height == settings.height) return ref;
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "  %s: unusable (%s); rendering it again\n", sidecar.c_str(), e.what());
    }
  }
  std::fprintf(stderr, "  reference %s: %d spp in %d passes...\n", ref.key.c_str(), spp, passes);
  const int pass_spp = spp / passes;
  error_model::PassMoments moments(settings.width, settings.height, pass_spp);
  std::vector<double> pass_energy;
  for (int k = 0; k < passes; ++k) {
    RenderSettings p = settings;
    p.ns_aa = pass_spp;
    p.seed = 1000000 + uint64_t(k);
    PathTracer tracer(s.loaded.scene, p);
    RenderResult r = render(tracer, opt.threads);
    if (!r.ok()) throw std::runtime_error("reference " + ref.key + ": " + r.error);
    moments.add(r.image);
    pass_energy.push_back(image_energy(r.image));
    ref.seconds += r.seconds;
  }
  ref.image = moments.mean();
  // The model's a is the relative variance of one sample with the weights of
  // the stored image; the N-spp mean contributes a / N to E[relMSE].
  const error_model::RelMSEModel model = moments.model(ref.image);
  ref.own_relmse = model.a / spp;
  ref.energy = image_energy(ref.image);
  double m = 0, m2 = 0;
  for (double e : pass_energy) m += e / passes;
  for (double e : pass_energy) m2 += (e - m) * (e - m) / (passes - 1);
  ref.energy_se = std::sqrt(m2 / passes);
  write_exr(exr.string(), ref.image);
  nlohmann::ordered_json j;
  j["key"] = ref.key;
  j["scene"] = s.entry.name;
  j["spp"] = spp;
  j["passes"] = passes;
  j["seeds"] = "1000000 + pass";
  j["width"] = settings.width;
  j["height"] = settings.height;
  j["max_depth"] = settings.max_ray_depth;
  j["light_samples"] = settings.ns_area_light;
  j["rr"] = settings.rr_continue_prob;
  j["hemisphere"] = settings.direct_hemisphere_sample;
  j["relative_variance_per_sample"] = model.a;
  j["own_relmse"] = ref.own_relmse;
  j["energy"] = ref.energy;
  j["energy_se"] = ref.energy_se;
  j["seconds"] = ref.seconds;
  std::ofstream(sidecar) << j.dump(2) << "\n";
  std::fprintf(stderr, "  reference %s: %.1f s\n", ref.key.c_str(), ref.seconds);
  return ref;
}

// --- Measurements -----------------------------------------------------------------------
namespace {
struct MeanSe {
  double n = 0, s = 0, s2 = 0;
  void add(double x) { ++n, s += x, s2 += x * x; }
  double mean() const { return n ? s / n : kNaN; }
  double se() const { return n > 1 ? std::sqrt(std::max(0.0, (s2 - s * s / n) / (n - 1)) / n) : kNaN; }
};
}  // namespace

Measurement measure(const Options& opt, const StudyScene& s, RenderSettings settings, const Reference* ref) {
  Measurement m;
  m.spp = settings.ns_aa;
  m.seeds = opt.seeds;
  MeanSe secs, rays, samples, relmse, bias;
  for (int k = 1; k <= opt.seeds; ++k) {
    settings.seed = uint64_t(k);
    PathTracer tracer(s.loaded.scene, settings);
    RenderResult r = render(tracer, opt.threads);
    if (!r.ok()) throw std::runtime_error(s.entry.name + ": " + r.error);
    secs.add(r.seconds);
    rays.add(double(r.work.rays));
    double n = 0;
    for (int c : r.sample_counts) n += c;
    samples.add(n / double(r.sample_counts.size()));
    if (ref) {
      relmse.add(compare_images(r.image, ref->image).relmse - ref->own_relmse);
      bias.add(image_energy(r.image) / ref->energy - 1.0);
    }
    if (k == 1) {
      m.first = std::move(r.image);
      m.first_counts = std::move(r.sample_counts);
    }
  }
  m.seconds = secs.mean();
  m.seconds_se = secs.se();
  m.rays = rays.mean();
  m.samples = samples.mean();
  if (ref) {
    m.relmse = relmse.mean();
    m.relmse_se = relmse.se();
    m.energy_bias = bias.mean();
    // The reference's own uncertainty in its energy adds in quadrature.
    const double ref_rel = ref->energy_se / ref->energy;
    m.energy_bias_se = std::sqrt(bias.se() * bias.se() + ref_rel * ref_rel);
  }
  return m;
}

void set_row(Table& t, const std::string& method, const std::string& parameter, double value, const Measurement& m,
             const Reference* ref) {
  t.row()
      .set("method", method)
      .set("parameter", parameter)
      .set("value", value)
      .set("samples", m.samples)
      .set("rays", m.rays)
      .set("wall_seconds", m.seconds)
      .set("wall_seconds_se", m.seconds_se)
      .set("relmse", m.relmse)
      .set("relmse_se", m.relmse_se)
      .set("seeds", m.seeds)
      .set("reference_spp", ref ? double(ref->spp) : kNaN);
}

// --- Curves ----------------------------------------------------------------------------
namespace {
double interp(const std::vector<double>& x, const std::vector<double>& y, double at, bool logs) {
  auto f = [&](double v) { return logs ? std::log(v) : v; };
  for (size_t i = 0; i + 1 < x.size(); ++i) {
    const double lo = std::min(x[i], x[i + 1]), hi = std::max(x[i], x[i + 1]);
    if (at < lo || at > hi) continue;
    if (logs && (x[i] <= 0 || x[i + 1] <= 0 || y[i] <= 0 || y[i + 1] <= 0)) return kNaN;
    if (x[i] == x[i + 1]) return y[i];
    const double w = (f(at) - f(x[i])) / (f(x[i + 1]) - f(x[i]));
    const double v = f(y[i]) + w * (f(y[i + 1]) - f(y[i]));
    return logs ? std::exp(v) : v;
  }
  return kNaN;
}
}  // namespace
double interp_loglog(const std::vector<double>& x, const std::vector<double>& y, double at) {
  return interp(x, y, at, true);
}
double interp_linear(const std::vector<double>& x, const std::vector<double>& y, double at) {
  return interp(x, y, at, false);
}

// --- Formatting --------------------------------------------------------------------------
std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string fmt2(const char* f, double a, double b) {
  char buf[128];
  std::snprintf(buf, sizeof buf, f, a, b);
  return buf;
}
std::string pm(double v, double se, const char* unit) {
  if (!std::isfinite(v)) return "n/a";
  if (!std::isfinite(se) || se <= 0) return fmt("%.3g", v) + unit;
  // Two significant digits of the error bar, the value to the same place.
  const int place = int(std::floor(std::log10(se))) - 1;
  const int decimals = std::max(0, -place);
  char buf[96];
  if (std::abs(v) >= 1e5 || (std::abs(v) < 1e-3 && v != 0)) {
    std::snprintf(buf, sizeof buf, "%.3g ± %.2g%s", v, se, unit);
  } else {
    std::snprintf(buf, sizeof buf, "%.*f ± %.*f%s", decimals, v, decimals, se, unit);
  }
  return buf;
}

void write_picture(const Options& opt, const std::string& file, const Image& img) {
  fs::create_directories((fs::path(opt.out) / file).parent_path());
  write_png((fs::path(opt.out) / file).string(), img);
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return f ? a + " " + b + " " + c : "unknown";
}

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace pt::study
