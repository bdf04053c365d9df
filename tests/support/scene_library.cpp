#include "support/scene_library.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/scene_loader.h"
#include "pt_source_dir.h"

namespace pt::library {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Reads one manifest object, refusing keys it does not know, so that a typo
// ("sampels") is an error rather than a silent default.
class Fields {
 public:
  Fields(const json& j, std::string where, const std::string& file) : j_(j), where_(std::move(where)), file_(file) {
    if (!j_.is_object()) fail("", "expected an object");
  }
  // Call after the last field: refuses the keys nobody asked for.
  void done() const {
    for (const auto& [key, value] : j_.items())
      if (!used_.count(key)) fail("/" + key, "unknown key \"" + key + "\"");
  }
  std::string text(const std::string& key, bool required = true) {
    const json* v = get(key, required);
    if (!v) return "";
    if (!v->is_string()) fail("/" + key, "expected a string");
    return v->get<std::string>();
  }
  long long integer(const std::string& key, long long lo, long long hi) {
    const json* v = get(key, true);
    if (!v->is_number_integer() || v->get<long long>() < lo || v->get<long long>() > hi)
      fail("/" + key, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v->get<long long>();
  }
  double number(const std::string& key, double lo, double hi) {
    const json* v = get(key, true);
    if (!v->is_number() || !(v->get<double>() >= lo && v->get<double>() <= hi))
      fail("/" + key, "expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v->get<double>();
  }
  Fields object(const std::string& key) { return Fields(*get(key, true), where_ + "/" + key, file_); }
  const json& array(const std::string& key) {
    const json* v = get(key, true);
    if (!v->is_array() || v->empty()) fail("/" + key, "expected a non-empty array");
    return *v;
  }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw std::runtime_error(file_ + ": " + where_ + key + ": " + what);
  }

 private:
  const json* get(const std::string& key, bool required) {
    used_.insert(key);
    auto it = j_.find(key);
    if (it == j_.end()) {
      if (required) fail("/" + key, "missing");
      return nullptr;
    }
    return &*it;
  }
  const json& j_;
  std::string where_;
  const std::string& file_;
  std::set<std::string> used_;
};

std::string quote(const std::string& s) {
  if (s.find_first_of(" '\"\\$`") == std::string::npos) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

RenderSettings LibraryScene::settings(int spp, uint64_t seed) const {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.ns_aa = spp;
  s.ns_area_light = light_samples;
  s.max_ray_depth = max_depth;
  s.rr_continue_prob = rr;
  s.seed = seed;
  return s;
}

std::vector<std::string> LibraryScene::arguments(int spp, uint64_t seed, const std::string& output) const {
  char rr_text[32];  // the shortest text that reads back as the same double
  *std::to_chars(rr_text, rr_text + sizeof rr_text - 1, rr).ptr = '\0';
  return {path, "-r", std::to_string(width), std::to_string(height), "-s", std::to_string(spp), "-l",
          std::to_string(light_samples), "-m", std::to_string(max_depth), "--rr", rr_text, "--seed",
          std::to_string(seed), "-q", "-f", output};
}

std::string LibraryScene::command(int spp, uint64_t seed, const std::string& output) const {
  const std::vector<std::string> args = arguments(spp, seed, output);
  std::string c = "pathtracer-reference";
  for (size_t i = 0; i < args.size(); ++i)
    c += " " + (i == 0 || i + 1 == args.size() ? quote(args[i]) : args[i]);
  return c;
}

const LibraryScene& Library::find(const std::string& name) const {
  for (const auto& s : scenes)
    if (s.name == name) return s;
  throw std::out_of_range(manifest + ": no scene named \"" + name + "\"");
}

std::string default_manifest() { return std::string(PT_SOURCE_DIR) + "/scenes/library.json"; }

Library load_library(const std::string& manifest, const std::string& generated_dir) {
  std::ifstream in(manifest);
  if (!in) throw std::runtime_error(manifest + ": cannot open the scene library");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(manifest + ": " + e.what());
  }
  Library lib;
  lib.manifest = manifest;
  lib.scenes_dir = fs::path(manifest).parent_path().string();
  lib.reference_dir = (fs::path(lib.scenes_dir) / "reference").string();
  Fields top(j, "", manifest);
  top.text("description");
  const json& list = top.array("scenes");
  top.done();
  const int kMaxSide = 4096, kMaxSamples = 1 << 20;
  for (size_t i = 0; i < list.size(); ++i) {
    Fields f(list[i], "/scenes/" + std::to_string(i), manifest);
    LibraryScene s;
    s.name = f.text("name");
    if (s.name.empty() || s.name.find_first_of("/\\ ") != std::string::npos)
      f.fail("/name", "expected a file stem (no spaces or slashes)");
    for (const auto& other : lib.scenes)
      if (other.name == s.name) f.fail("/name", "duplicate name \"" + s.name + "\"");
    s.file = f.text("file");
    s.purpose = f.text("purpose");
    s.generated = f.text("generated", false);
    s.path = (fs::path(s.generated.empty() ? lib.scenes_dir : generated_dir) / s.file).string();
    {
      Fields r = f.object("render");
      s.width = int(r.integer("width", 1, kMaxSide));
      s.height = int(r.integer("height", 1, kMaxSide));
      s.light_samples = int(r.integer("light_samples", 1, 1024));
      s.max_depth = int(r.integer("max_depth", 0, 1000));
      s.rr = r.number("rr", 1e-3, 1.0);
      r.done();
    }
    {
      Fields r = f.object("reference");
      s.reference_samples = int(r.integer("samples", 2, kMaxSamples));
      s.pass_samples = int(r.integer("pass_samples", 2, kMaxSamples));
      s.reference_seed = uint64_t(r.integer("seed", 0, std::numeric_limits<long long>::max()));
      // Two passes at least (a variance needs them); one sample per pixel is
      // the pixel centre, not a jittered sample, so passes take two or more.
      if (s.reference_samples % s.pass_samples != 0 || s.passes() < 2)
        r.fail("/samples", "expected a multiple (at least twice) of pass_samples");
      r.done();
    }
    {
      Fields c = f.object("check");
      s.check_samples = int(c.integer("samples", 2, kMaxSamples));
      s.check_seed = uint64_t(c.integer("seed", 0, std::numeric_limits<long long>::max()));
      // The check must be independent of the reference: no shared seed.
      if (s.check_seed >= s.reference_seed && s.check_seed < s.reference_seed + uint64_t(s.passes()))
        c.fail("/seed", "must differ from the reference's seeds " + std::to_string(s.reference_seed) + " to " +
                            std::to_string(s.reference_seed + s.passes() - 1));
      c.done();
    }
    f.done();
    lib.scenes.push_back(std::move(s));
  }
  return lib;
}

LoadedScene load(const LibraryScene& s) {
  LoadedScene loaded = load_scene(s.path);
  loaded.scene.camera.set_aspect(double(s.width) / s.height);  // as the command line does
  return loaded;
}

RenderResult render(const LibraryScene& s, const Scene& scene, int spp, uint64_t seed, int threads) {
  PathTracer tracer(scene, s.settings(spp, seed));
  return pt::render(tracer, threads);
}

}  // namespace pt::library
