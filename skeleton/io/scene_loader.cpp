// The JSON scene format; scenes/README.md documents every key. Every value
// read is checked, and an error names the file and the JSON pointer of the
// value, so that a typo never turns silently into a default.
#include "io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

#include "render/settings.h"
#include "io/collada_loader.h"
#include "io/input_file.h"
#include "io/json_reader.h"
#include "io/obj_loader.h"

namespace fs = std::filesystem;

namespace pt {

namespace {

const Spectrum kWhite(1.0);
// Used by shapes that name no material; Mitsuba's default reflectance.
const Spectrum kDefaultAlbedo(0.5);

Camera read_camera(const JsonReader& r, const json& j, const std::string& at) {
  r.expect_object(j, at, {"position", "target", "up", "vfov", "hfov", "near", "far"});
  Vec3 position = r.vec3_or(j, at, "position", Vec3(0.0), Range::Any);
  Vec3 target = r.vec3_or(j, at, "target", Vec3(0.0, 0.0, -1.0), Range::Any);
  Vec3 up = j.contains("up") ? r.nonzero_vec3(j["up"], child(at, "up")) : Vec3(0.0, 1.0, 0.0);
  if (target == position) r.fail(child(at, "target"), "must differ from the camera position");
  if (glm::length(glm::cross(up, target - position)) <= 1e-9 * glm::length(up) * glm::length(target - position))
    r.fail(child(at, "up"), "must not be parallel to the viewing direction");

  auto fov = [&](const char* key, double fallback) {
    double deg = r.number_or(j, at, key, fallback, Range::Positive);
    if (deg >= 180.0) r.fail(child(at, key), "expected an angle in (0, 180) degrees, got " + format_number(deg));
    return deg;
  };
  double vfov = fov("vfov", 35.0);
  double near = r.number_or(j, at, "near", 1e-4, Range::Positive);
  double far = r.number_or(j, at, "far", 1e30, Range::Positive);
  if (far <= near) r.fail(child(at, "far"), "must be greater than near (" + format_number(near) + ")");

  Camera cam(position, target, up, vfov, vfov, near, far);
  // Without an hfov, the one the default resolution gives; the renderer sets
  // it from the actual image size anyway (Camera::set_aspect).
  if (j.contains("hfov")) cam.hfov = fov("hfov", 0.0);
  else cam.set_aspect(double(RenderSettings{}.width) / RenderSettings{}.height);
  return cam;
}

// Reads one scene file into `out`. Keeps what the shapes need while they are
// read: the directory mesh paths are relative to, and the named materials.
class JsonSceneLoader {
 public:
  JsonSceneLoader(const std::string& path, LoadedScene* out)
      : r_(path), dir_(fs::path(path).parent_path()), out_(out), scene_(out->scene) {}

  void load() {
    json doc = parse_json_file(r_.file(), "a scene file");
    r_.expect_object(doc, "", {"description", "camera", "materials", "lights", "shapes"});
    if (doc.contains("description")) r_.string(doc["description"], "/description");
    // Read even when absent, so that a scene without one gets the documented defaults.
    scene_.camera = read_camera(r_, doc.contains("camera") ? doc["camera"] : json::object(), "/camera");
    if (doc.contains("materials")) read_materials(doc["materials"], "/materials");
    if (doc.contains("lights")) {
      r_.expect_array(doc["lights"], "/lights");
      for (size_t i = 0; i < doc["lights"].size(); ++i) read_light(doc["lights"][i], child("/lights", i));
    }
    const json& shapes = r_.required(doc, "", "shapes");
    r_.expect_array(shapes, "/shapes");
    if (shapes.empty()) r_.fail("/shapes", "a scene needs at least one shape");
    for (size_t i = 0; i < shapes.size(); ++i) read_shape(shapes[i], child("/shapes", i));
  }

 private:
  JsonReader r_;
  fs::path dir_;
  LoadedScene* out_;
  Scene& scene_;
  std::map<std::string, const BSDF*> materials_;
  const BSDF* default_material_ = nullptr;

  // The object's "type", checked against the types this place accepts.
  std::string type_of(const json& j, const std::string& at, std::initializer_list<const char*> types) const {
    if (!j.is_object()) r_.fail(at, "expected an object with a \"type\"");
    std::string type = r_.string(r_.required(j, at, "type"), child(at, "type"));
    std::string list;
    for (const char* t : types) {
      if (type == t) return type;
      list += (list.empty() ? "" : ", ") + std::string(t);
    }
    r_.fail(child(at, "type"), "unknown type \"" + type + "\" (expected one of: " + list + ")");
  }

  void read_materials(const json& j, const std::string& at) {
    if (!j.is_object()) r_.fail(at, "expected an object mapping names to materials");
    for (const auto& [name, m] : j.items()) {
      std::string here = child(at, name);
      std::string type = type_of(m, here, {"diffuse", "emission"});
      if (type == "diffuse") {
        r_.expect_object(m, here, {"type", "albedo"});
        materials_[name] = scene_.add_bsdf<DiffuseBSDF>(r_.vec3_or(m, here, "albedo", kDefaultAlbedo, Range::Unit));
      } else {
        r_.expect_object(m, here, {"type", "radiance"});
        materials_[name] = scene_.add_bsdf<EmissionBSDF>(r_.vec3_or(m, here, "radiance", kWhite, Range::NonNegative));
      }
    }
  }

  void read_light(const json& j, const std::string& at) {
    std::string type = type_of(j, at, {"area", "point", "directional", "sky"});
    if (type == "area") {
      r_.expect_object(j, at, {"type", "radiance", "center", "edge_x", "edge_y"});
      Vec3 center = r_.vec3(r_.required(j, at, "center"), child(at, "center"), Range::Any);
      auto [ex, ey] = read_edges(j, at);
      scene_.add_area_light(r_.vec3_or(j, at, "radiance", kWhite, Range::NonNegative), center, ex, ey);
    } else if (type == "point") {
      r_.expect_object(j, at, {"type", "intensity", "position"});
      Vec3 position = r_.vec3(r_.required(j, at, "position"), child(at, "position"), Range::Any);
      scene_.add_light<PointLight>(r_.vec3_or(j, at, "intensity", kWhite, Range::NonNegative), position);
    } else if (type == "directional") {
      r_.expect_object(j, at, {"type", "radiance", "direction"});
      Vec3 direction = r_.nonzero_vec3(r_.required(j, at, "direction"), child(at, "direction"));
      scene_.add_light<DirectionalLight>(r_.vec3_or(j, at, "radiance", kWhite, Range::NonNegative), direction);
    } else {
      r_.expect_object(j, at, {"type", "radiance"});
      scene_.add_light<SkyLight>(r_.vec3_or(j, at, "radiance", kWhite, Range::NonNegative));
    }
  }

  // The two edges of a parallelogram; they must span a plane.
  std::pair<Vec3, Vec3> read_edges(const json& j, const std::string& at) const {
    Vec3 ex = r_.nonzero_vec3(r_.required(j, at, "edge_x"), child(at, "edge_x"));
    Vec3 ey = r_.nonzero_vec3(r_.required(j, at, "edge_y"), child(at, "edge_y"));
    if (glm::length(glm::cross(ex, ey)) <= 1e-12 * glm::length(ex) * glm::length(ey))
      r_.fail(child(at, "edge_y"), "must not be parallel to edge_x");
    return {ex, ey};
  }

  void read_shape(const json& j, const std::string& at) {
    std::string type = type_of(j, at, {"sphere", "quad", "mesh"});
    if (type == "sphere") {
      r_.expect_object(j, at, {"type", "center", "radius", "material"});
      Vec3 center = r_.vec3(r_.required(j, at, "center"), child(at, "center"), Range::Any);
      double radius = r_.number(r_.required(j, at, "radius"), child(at, "radius"), Range::Positive);
      scene_.add_sphere(center, radius, material(j, at, type));
    } else if (type == "quad") {
      r_.expect_object(j, at, {"type", "center", "edge_x", "edge_y", "material"});
      Vec3 center = r_.vec3(r_.required(j, at, "center"), child(at, "center"), Range::Any);
      auto [ex, ey] = read_edges(j, at);
      scene_.add_quad(center, ex, ey, material(j, at, type));
    } else {
      r_.expect_object(j, at, {"type", "file", "material", "transform"});
      read_mesh(j, at);
    }
  }

  void read_mesh(const json& j, const std::string& at) {
    std::string file_at = child(at, "file");
    fs::path file = r_.string(r_.required(j, at, "file"), file_at);
    // Relative to the scene file, so that scenes load from any working directory.
    fs::path resolved = file.is_absolute() ? file : dir_ / file;
    MeshTransform transform = j.contains("transform") ? read_transform(j["transform"], child(at, "transform"))
                                                      : MeshTransform{};
    const BSDF* bsdf = material(j, at, "mesh");
    std::vector<std::string> obj_warnings;
    Mesh mesh;
    try {
      mesh = load_obj(resolved.string(), transform, &obj_warnings);
    } catch (const SceneError& e) {
      r_.fail(file_at, e.what());
    }
    for (const auto& w : obj_warnings) out_->warnings.push_back(at + ": " + w);
    mesh.bsdf = bsdf;
    scene_.add_mesh(std::move(mesh));
  }

  MeshTransform read_transform(const json& j, const std::string& at) const {
    r_.expect_object(j, at, {"scale", "rotate", "translate"});
    MeshTransform t;
    if (j.contains("scale")) {
      const json& s = j["scale"];
      t.scale = s.is_number() ? Vec3(r_.number(s, child(at, "scale"), Range::Positive))
                              : r_.vec3(s, child(at, "scale"), Range::Positive);
    }
    if (j.contains("rotate")) {
      std::string rot_at = child(at, "rotate");
      const json& rot = j["rotate"];
      r_.expect_object(rot, rot_at, {"axis", "degrees"});
      if (rot.contains("axis")) t.axis = r_.nonzero_vec3(rot["axis"], child(rot_at, "axis"));
      t.degrees = r_.number(r_.required(rot, rot_at, "degrees"), child(rot_at, "degrees"), Range::Any);
    }
    t.translate = r_.vec3_or(j, at, "translate", Vec3(0.0), Range::Any);
    return t;
  }

  // The shape's named material, or a shared grey diffuse one when it names none.
  const BSDF* material(const json& j, const std::string& at, const std::string& shape) {
    if (!j.contains("material")) {
      if (!default_material_) default_material_ = scene_.add_bsdf<DiffuseBSDF>(kDefaultAlbedo);
      return default_material_;
    }
    std::string name = r_.string(j["material"], child(at, "material"));
    auto it = materials_.find(name);
    if (it == materials_.end()) {
      std::string known;
      for (const auto& m : materials_) known += (known.empty() ? "" : ", ") + m.first;
      r_.fail(child(at, "material"), "unknown material \"" + name + "\" (" +
                                         (known.empty() ? "no materials are defined" : "defined: " + known) + ")");
    }
    // The estimators sample only the scene's lights, so an emitting shape
    // lights nothing under light sampling (nor in indirect bounces).
    if (dynamic_cast<const EmissionBSDF*>(it->second))
      out_->warnings.push_back(at + ": this " + shape + " uses emission material \"" + name +
                               "\": camera rays and hemisphere sampling see it, but it is not a light "
                               "(light sampling and indirect bounces ignore it; use an \"area\" light)");
    return it->second;
  }
};

std::string lowercase_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

LoadedScene load_scene(const std::string& path, BuildBvh bvh) {
  LoadedScene out;
  std::string ext = lowercase_extension(path);
  check_input_path(path, "a scene file");
  if (ext == ".json") JsonSceneLoader(path, &out).load();
  else if (ext == ".dae") load_collada(path, &out);
  else throw SceneError(path + ": unknown scene format \"" + ext + "\" (expected .json or .dae)");
  if (bvh == BuildBvh::Yes) out.scene.build();
  return out;
}

Camera load_camera(const std::string& path) {
  JsonReader r(path);
  return read_camera(r, parse_json_file(path, "a camera file"), "");
}

}  // namespace pt
