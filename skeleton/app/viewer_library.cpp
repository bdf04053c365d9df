#include "app/viewer_library.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/image_file.h"

namespace pt {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {
json read_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}
}  // namespace

std::optional<LibraryReference> find_library_reference(const std::string& scene_path) {
  std::error_code ec;
  const fs::path scene = fs::weakly_canonical(scene_path, ec);
  const fs::path dir = scene.parent_path(), library = dir / "library.json";
  if (ec || !fs::exists(library, ec)) return std::nullopt;
  const json lib = read_json(library);
  if (!lib.contains("scenes") || !lib["scenes"].is_array()) return std::nullopt;
  for (const json& entry : lib["scenes"]) {
    if (!entry.contains("file") || !entry["file"].is_string() || entry.contains("generated")) continue;
    if (fs::weakly_canonical(dir / entry["file"].get<std::string>(), ec) != scene) continue;
    LibraryReference ref;
    ref.name = entry.at("name").get<std::string>();
    const json render = entry.value("render", json::object());
    ref.settings.width = render.value("width", ref.settings.width);
    ref.settings.height = render.value("height", ref.settings.height);
    ref.settings.ns_area_light = render.value("light_samples", ref.settings.ns_area_light);
    ref.settings.max_ray_depth = render.value("max_depth", ref.settings.max_ray_depth);
    ref.settings.rr_continue_prob = render.value("rr", ref.settings.rr_continue_prob);
    ref.image = read_exr((dir / "reference" / (ref.name + ".exr")).string());
    const json model = read_json(dir / "reference" / (ref.name + ".json")).at("error_model");
    ref.model.a = model.at("a").get<double>();
    ref.model.c2 = model.at("c2").get<double>();
    ref.model.c3 = model.at("c3").get<double>();
    ref.model.reference_samples = model.at("reference_samples").get<int>();
    return ref;
  }
  return std::nullopt;
}

}  // namespace pt
