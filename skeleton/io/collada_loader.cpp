// The COLLADA importer: walks the visual scene's node graph and adds its
// meshes, CGL spheres, lights and camera to a Scene. Every place a value comes
// from is named in errors and warnings by its element path; what the
// framework does not model (materials beyond diffuse and emission, ...) is
// approximated with a warning.
#include "io/collada_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "render/settings.h"
#include "io/collada_document.h"
#include "io/collada_mesh.h"
#include "scene/course_camera.h"
#include "io/scene_text.h"

namespace pt {

namespace {

const Spectrum kDefaultAlbedo(0.5);  // no material: the course's grey

bool is(const char* a, const char* b) { return std::strcmp(a, b) == 0; }

std::string trimmed(const char* s) {
  std::string t(s);
  const char* ws = " \t\r\n";
  size_t b = t.find_first_not_of(ws), e = t.find_last_not_of(ws);
  return b == std::string::npos ? "" : t.substr(b, e - b + 1);
}

std::string format_vec(const Vec3& v) {
  return "(" + format_number(v.x) + ", " + format_number(v.y) + ", " + format_number(v.z) + ")";
}

Vec3 point(const Mat4& m, const Vec3& p) { return Vec3(m * glm::dvec4(p, 1.0)); }
Vec3 vector(const Mat4& m, const Vec3& v) { return Vec3(m * glm::dvec4(v, 0.0)); }

// The <technique profile="CGL"> among e's <extra>s (empty when none).
XmlNode cgl_technique(XmlNode e) {
  for (XmlNode extra : e.children("extra"))
    for (XmlNode t : extra.children("technique"))
      if (is(t.attribute("profile").value(), "CGL")) return t;
  return XmlNode();
}

XmlNode first_child_element(XmlNode e) {
  for (XmlNode c : e.children())
    if (c.type() == pugi::node_element) return c;
  return XmlNode();
}

class ColladaLoader {
 public:
  ColladaLoader(const std::string& path, LoadedScene* out, const ColladaLimits& limits)
      : doc_(path, &out->warnings, limits.max_warnings), limits_(limits), scene_(out->scene) {}

  void load() {
    XmlNode root = doc_.root();
    check_asset(root);
    XmlNode visual_scene = chosen_visual_scene(root);
    const Mat4 up = up_axis_conversion(root);
    for (XmlNode node : visual_scene.children("node")) visit(node, up, 1);

    if (scene_.primitives.empty())
      doc_.fail(visual_scene, "the visual scene has no geometry (no mesh or CGL sphere is instanced)");
    if (cameras_ == 0 || degenerate_camera_) {
      const std::string framing = "using one that looks along -z at the scene's centre from 1.5x its bounding "
                                  "box's diagonal";
      if (cameras_ == 0) {
        doc_.warn(visual_scene, "no camera: " + framing + " (the framing --course-camera gives)");
        // The course's loader defaults to hfov 50, vfov 35.
        scene_.camera = Camera(Vec3(0.0), Vec3(0.0, 0.0, -1.0), Vec3(0.0, 1.0, 0.0), 50.0, 35.0);
      } else {
        doc_.warn(degenerate_camera_, "a short <matrix> leaves the camera no position, view or up direction: " + framing);
      }
      RenderSettings defaults;  // the camera add_camera left looks along -z with the file's fovs
      scene_.camera = course_camera(scene_.camera, scene_.bounds(), defaults.width, defaults.height);
    }
    if (cameras_ > 1) {
      doc_.warn(first_camera_, "the scene instances " + std::to_string(cameras_) + " cameras: the first one is used");
    }
    if (specular_materials_ > 0)
      doc_.warn(root, std::to_string(specular_materials_) +
                          " material(s) have a specular or reflective colour: only the diffuse colour is used, as "
                          "in the course's renderer");
    if (point_attenuation_)
      doc_.warn(point_attenuation_, "point light attenuation ignored: intensity falls off as 1/d^2, as in the "
                                    "course's renderer");
    if (emissive_shapes_ > 0 && area_lights_ == 0)
      doc_.warn(visual_scene, std::to_string(emissive_shapes_) +
                                  " shape(s) emit light but the scene has no area light: camera rays and hemisphere "
                                  "sampling see them, light sampling (the default) does not");
    doc_.finish();
  }

 private:
  ColladaDocument doc_;
  ColladaLimits limits_;
  Scene& scene_;

  std::map<const void*, std::vector<ColladaMeshPart>> meshes_;  // by <mesh>, read once
  std::map<const void*, const BSDF*> bsdfs_;                    // by <material>, made once
  std::set<const void*> warned_;                                // elements already warned about
  const BSDF* default_bsdf_ = nullptr;
  std::vector<XmlNode> path_;  // nodes being visited, outermost first: finds cycles
  size_t node_visits_ = 0, triangles_ = 0;
  size_t cameras_ = 0, area_lights_ = 0, emissive_shapes_ = 0, specular_materials_ = 0;
  XmlNode first_camera_, point_attenuation_;
  XmlNode degenerate_camera_;          // the first camera, when a short <matrix> left it unusable
  size_t short_matrices_on_path_ = 0;  // <matrix> elements of fewer than 16 numbers above this node

  // Warns about element e once, however often the graph instances it.
  void warn_once(XmlNode e, const std::string& message) {
    if (warned_.insert(e.internal_object()).second) doc_.warn(e, message);
  }

  void check_asset(XmlNode root) {
    std::string version = root.attribute("version").value();
    if (version.rfind("1.4", 0) != 0)
      doc_.warn(root, "COLLADA version \"" + ColladaDocument::quoted(version) + "\" is read as 1.4.1");
    if (XmlNode unit = root.child("asset").child("unit")) {
      std::string meter = unit.attribute("meter").value();
      if (!meter.empty() && meter != "1" && meter != "1.0")
        doc_.warn(unit, "unit meter=\"" + ColladaDocument::quoted(meter) +
                            "\" ignored: lengths are used as written, as the course's loader does");
    }
    if (XmlNode animations = root.child("library_animations"); first_child_element(animations))
      doc_.warn(animations, "animations ignored: the scene is rendered in the pose its nodes give");
  }

  XmlNode chosen_visual_scene(XmlNode root) {
    if (XmlNode instance = root.child("scene").child("instance_visual_scene"))
      return doc_.resolve(instance, "url", "visual_scene");
    XmlNode first = root.child("library_visual_scenes").child("visual_scene");
    if (!first) doc_.fail(root, "no <scene><instance_visual_scene> and no <visual_scene>: nothing to render");
    doc_.warn(first, "no <scene><instance_visual_scene> chooses a visual scene: using the first one");
    return first;
  }

  // The framework's world is y-up. Z_UP is converted as the course's loader
  // does, (x, y, z) -> (-x, z, y), and X_UP likewise, (x, y, z) -> (y, x, -z):
  // both are rotations, so windings and handedness are kept.
  Mat4 up_axis_conversion(XmlNode root) {
    Mat4 m(1.0);
    XmlNode up = root.child("asset").child("up_axis");
    if (!up) return m;  // COLLADA's default, Y_UP
    std::string axis = trimmed(up.text().get());
    if (axis == "Y_UP") return m;
    m = Mat4(0.0);
    m[3][3] = 1.0;
    if (axis == "Z_UP") {
      m[0][0] = -1.0, m[1][2] = 1.0, m[2][1] = 1.0;  // columns: the images of x, y and z
    } else if (axis == "X_UP") {
      m[0][1] = 1.0, m[1][0] = 1.0, m[2][2] = -1.0;
    } else {
      doc_.fail(up, "expected X_UP, Y_UP or Z_UP, got \"" + ColladaDocument::quoted(axis) + "\"");
    }
    return m;
  }

  // The node's own transform: its <matrix>, <translate>, <rotate>, <scale>
  // and <lookat> elements multiplied in document order. *short_matrix is set
  // when a <matrix> had fewer than 16 numbers.
  Mat4 local_transform(XmlNode node, bool* short_matrix) {
    Mat4 m(1.0);
    for (XmlNode e : node.children()) {
      if (e.type() != pugi::node_element) continue;
      const char* name = e.name();
      if (is(name, "matrix")) {
        std::vector<double> v = doc_.numbers(e);  // row-major
        if (v.size() > 16) doc_.fail(e, "expected 16 numbers, got " + std::to_string(v.size()));
        const bool short_one = v.size() < 16;
        if (short_one) {
          // The course's files have one (CBgems.dae's camera: 15 numbers), and
          // the course's reader takes it: its stream read leaves the rest 0.
          doc_.warn(e, "expected 16 numbers, got " + std::to_string(v.size()) +
                           ": the missing ones are read as 0, as the course's reader does");
          v.resize(16, 0.0);
          *short_matrix = true;
        }
        Mat4 t;
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c) t[c][r] = v[4 * r + c];
        // A short matrix keeps the last row it reads (a point's w is dropped,
        // as in the course's renderer); a full one must be affine.
        if (!short_one && (t[0][3] != 0.0 || t[1][3] != 0.0 || t[2][3] != 0.0 || t[3][3] != 1.0))
          doc_.fail(e, "the last row must be 0 0 0 1 (a projective transform places nothing)");
        m *= t;
      } else if (is(name, "translate")) {
        m = glm::translate(m, doc_.vec3(e));
      } else if (is(name, "scale")) {
        m = glm::scale(m, doc_.vec3(e));
      } else if (is(name, "rotate")) {
        std::vector<double> v = doc_.numbers(e, 4);  // axis x y z, angle in degrees
        Vec3 axis(v[0], v[1], v[2]);
        if (glm::length(axis) == 0.0) doc_.fail(e, "the rotation axis must not be zero");
        m = glm::rotate(m, glm::radians(v[3]), glm::normalize(axis));
      } else if (is(name, "lookat")) {
        std::vector<double> v = doc_.numbers(e, 9);  // eye, interest, up
        Vec3 eye(v[0], v[1], v[2]), back = eye - Vec3(v[3], v[4], v[5]), up(v[6], v[7], v[8]);
        Vec3 right = glm::cross(up, back);
        if (glm::length(back) == 0.0 || glm::length(right) == 0.0)
          doc_.fail(e, "eye and interest must differ, and up must not be parallel to the view");
        back = glm::normalize(back), right = glm::normalize(right);
        m *= Mat4(glm::dvec4(right, 0.0), glm::dvec4(glm::cross(back, right), 0.0), glm::dvec4(back, 0.0),
                  glm::dvec4(eye, 1.0));
      } else if (is(name, "skew")) {
        warn_once(e, "<skew> ignored");
      }
    }
    return m;
  }

  void visit(XmlNode node, const Mat4& parent, size_t depth) {
    if (depth > limits_.max_node_depth)
      doc_.fail(node, "nodes nested more than " + std::to_string(limits_.max_node_depth) +
                          " deep (through <node> and <instance_node>)");
    if (++node_visits_ > limits_.max_node_instances)
      doc_.fail(node, "more than " + std::to_string(limits_.max_node_instances) +
                          " node instances (<instance_node> repeats subtrees)");
    path_.push_back(node);
    bool short_matrix = false;
    const Mat4 world = parent * local_transform(node, &short_matrix);
    short_matrices_on_path_ += short_matrix;
    for (XmlNode e : node.children()) {
      if (e.type() != pugi::node_element) continue;
      const char* name = e.name();
      if (is(name, "node")) visit(e, world, depth + 1);
      else if (is(name, "instance_node")) visit(instanced_node(e), world, depth + 1);
      else if (is(name, "instance_geometry")) add_geometry(e, world);
      else if (is(name, "instance_light")) add_light(e, world);
      else if (is(name, "instance_camera")) add_camera(e, world);
      else if (is(name, "instance_controller"))
        warn_once(e, "skinned or morphed geometry (<instance_controller>) is not supported: ignored");
    }
    short_matrices_on_path_ -= short_matrix;
    path_.pop_back();
  }

  XmlNode instanced_node(XmlNode instance) {
    XmlNode target = doc_.resolve(instance, "url", "node");
    auto on_path = std::find(path_.begin(), path_.end(), target);
    if (on_path != path_.end()) {
      std::string cycle;
      for (auto it = on_path; it != path_.end(); ++it)
        cycle += "'" + ColladaDocument::quoted(it->attribute("id").value()) + "' -> ";
      doc_.fail(instance, "<instance_node> makes a cycle: " + cycle + "'" +
                              ColladaDocument::quoted(target.attribute("id").value()) + "'");
    }
    return target;
  }

  // --- Geometry -------------------------------------------------------------

  void add_geometry(XmlNode instance, const Mat4& world) {
    XmlNode geometry = doc_.resolve(instance, "url", "geometry");
    if (XmlNode mesh = geometry.child("mesh")) {
      auto it = meshes_.find(mesh.internal_object());
      if (it == meshes_.end()) it = meshes_.emplace(mesh.internal_object(), read_collada_mesh(doc_, mesh)).first;
      size_t faces = 0;
      for (const ColladaMeshPart& part : it->second) {
        add_mesh(instance, geometry, part, world);
        faces += part.faces.size();
      }
      if (faces == 0) warn_once(geometry, "has no faces: nothing of it is rendered");
      return;
    }
    if (XmlNode sphere = cgl_technique(geometry).child("sphere")) {
      add_sphere(instance, sphere, world);
      return;
    }
    warn_once(geometry, "has neither a <mesh> nor a CGL <sphere> (convex meshes, splines and B-reps are not "
                        "supported): ignored");
  }

  void add_mesh(XmlNode instance, XmlNode geometry, const ColladaMeshPart& part, const Mat4& world) {
    if (part.faces.empty()) return;
    triangles_ += part.faces.size();
    if (triangles_ > limits_.max_triangles)
      doc_.fail(instance, "the scene has more than " + std::to_string(limits_.max_triangles) +
                              " triangles after instancing");
    Mesh mesh;
    mesh.name = geometry.attribute("id").value();
    mesh.positions.reserve(part.positions.size());
    for (const Vec3& p : part.positions) mesh.positions.push_back(placed(instance, point(world, p), "a vertex"));
    // Normals by the inverse transpose, so that they stay perpendicular under
    // non-uniform scale; a singular transform flattens the mesh, whose normals
    // are then recomputed.
    Mat3 linear(world);
    double det = glm::determinant(linear);
    if (!part.normals.empty() && std::isfinite(det) && det != 0.0) {
      Mat3 normal_matrix = glm::transpose(glm::inverse(linear));
      for (const Vec3& n : part.normals) mesh.normals.push_back(glm::normalize(normal_matrix * n));
      if (!std::all_of(mesh.normals.begin(), mesh.normals.end(), [](const Vec3& n) { return is_finite(n); }))
        mesh.normals.clear();
    }
    mesh.faces = part.faces;
    mesh.bsdf = bound_material(instance, part.material);
    emissive_shapes_ += is_emitter(mesh.bsdf);
    scene_.add_mesh(std::move(mesh));
  }

  // A CGL sphere: centre T * origin, radius scaled by |T * x| (the course's rule).
  void add_sphere(XmlNode instance, XmlNode sphere, const Mat4& world) {
    XmlNode radius_element = doc_.child(sphere, "radius");
    double radius = doc_.number(radius_element);
    if (!(radius > 0.0)) doc_.fail(radius_element, "expected a positive radius, got " + format_number(radius));
    Vec3 centre = placed(instance, point(world, Vec3(0.0)), "the sphere's centre");
    double sx = glm::length(vector(world, Vec3(1, 0, 0))), sy = glm::length(vector(world, Vec3(0, 1, 0))),
           sz = glm::length(vector(world, Vec3(0, 0, 1)));
    double r = radius * sx;
    if (!(r > 0.0) || !std::isfinite(r) || r > kMaxMagnitude)
      doc_.fail(instance, "the node transforms make the sphere's radius " + format_number(r) +
                              " (expected positive and at most 1e30)");
    if (std::abs(sy - sx) > 1e-6 * sx || std::abs(sz - sx) > 1e-6 * sx)
      warn_once(instance, "a sphere under a non-uniform scale stays a sphere, of radius " + format_number(r) +
                              " (the radius times the scale of x, as in the course's loader)");
    const BSDF* bsdf = bound_material(instance, "");
    emissive_shapes_ += is_emitter(bsdf);
    scene_.add_sphere(centre, r, bsdf);
  }

  static bool usable(const Vec3& v) { return is_finite(v) && max_component(glm::abs(v)) <= kMaxMagnitude; }

  // A transformed point or vector, which must stay finite and at most 1e30.
  Vec3 placed(XmlNode instance, const Vec3& v, const char* what) {
    if (!usable(v))
      doc_.fail(instance, std::string("the node transforms put ") + what + " at " + format_vec(v) +
                              ", beyond 1e30");
    return v;
  }

  static bool is_emitter(const BSDF* bsdf) { return bsdf->get_emission(Vec3(0.0, 0.0, 1.0)) != Spectrum(0.0); }

  // --- Materials ------------------------------------------------------------

  // The material bound to `symbol` in instance's <bind_material>; when the
  // symbol is not bound (or the element names none), the first bound one, as
  // the course's loader does; with no binding at all, grey 0.5.
  const BSDF* bound_material(XmlNode instance, const std::string& symbol) {
    XmlNode chosen, first;
    for (XmlNode im : instance.child("bind_material").child("technique_common").children("instance_material")) {
      if (!first) first = im;
      if (!symbol.empty() && symbol == im.attribute("symbol").value()) {
        chosen = im;
        break;
      }
    }
    if (!chosen && first) {
      chosen = first;
      if (!symbol.empty())
        warn_once(instance, "material symbol '" + ColladaDocument::quoted(symbol) +
                                "' is not bound here: using the first <instance_material>");
    }
    if (!chosen) {
      if (!default_bsdf_) default_bsdf_ = scene_.add_bsdf<DiffuseBSDF>(kDefaultAlbedo);
      return default_bsdf_;
    }
    XmlNode material = doc_.resolve(chosen, "target", "material");
    auto it = bsdfs_.find(material.internal_object());
    if (it == bsdfs_.end()) it = bsdfs_.emplace(material.internal_object(), make_bsdf(material)).first;
    return it->second;
  }

  // Precedence (the course's): a CGL <emission><radiance> makes an emitter;
  // else the phong / lambert / blinn <diffuse><color>; else grey 0.5. What
  // the framework does not model is listed in one warning per material.
  const BSDF* make_bsdf(XmlNode material) {
    XmlNode effect = doc_.resolve(doc_.child(material, "instance_effect"), "url", "effect");
    std::vector<std::string> approximated;
    Spectrum albedo = kDefaultAlbedo;

    XmlNode technique = effect.child("profile_COMMON").child("technique");
    XmlNode shading;
    for (XmlNode e : technique.children())
      if (is(e.name(), "phong") || is(e.name(), "lambert") || is(e.name(), "blinn") || is(e.name(), "constant")) {
        shading = e;
        break;
      }
    if (shading) {
      XmlNode diffuse = shading.child("diffuse");
      if (XmlNode c = diffuse.child("color")) albedo = doc_.color(c);
      else if (diffuse.child("texture")) approximated.push_back("a diffuse <texture>");
      else if (is(shading.name(), "constant")) approximated.push_back("<constant> (unlit) shading");
      for (const char* name : {"specular", "reflective"})
        if (XmlNode c = shading.child(name).child("color"); c && doc_.color(c) != Spectrum(0.0)) {
          ++specular_materials_;
          break;
        }
      if (XmlNode c = shading.child("emission").child("color"); c && doc_.color(c) != Spectrum(0.0))
        approximated.push_back("a profile_COMMON <emission> colour (only a CGL <emission><radiance> emits)");
    }
    // The CGL extension sits in the effect's <extra> (or in its profile's).
    XmlNode cgl = cgl_technique(effect);
    if (!cgl) cgl = cgl_technique(effect.child("profile_COMMON"));
    if (!cgl) cgl = cgl_technique(technique);
    std::optional<Spectrum> emission;
    for (XmlNode e : cgl.children()) {
      if (e.type() != pugi::node_element) continue;
      if (is(e.name(), "emission")) emission = doc_.color(doc_.child(e, "radiance"));
      else approximated.push_back("CGL <" + ColladaDocument::quoted(e.name()) + ">");
    }
    if (!emission && std::max({albedo.r, albedo.g, albedo.b}) > 1.0) {
      approximated.push_back("a diffuse colour above 1, " + format_vec(albedo) + ", clamped");
      albedo = glm::min(albedo, Spectrum(1.0));
    }
    if (!approximated.empty()) {
      std::string list;
      for (const auto& a : approximated) list += (list.empty() ? "" : ", ") + a;
      doc_.warn(material, list + ": not in this framework's model (Lambertian diffuse and emission); imported as " +
                              (emission ? "an emitter of radiance " + format_vec(*emission)
                                        : "diffuse, albedo " + format_vec(albedo)));
    }
    if (emission) return scene_.add_bsdf<EmissionBSDF>(*emission);
    return scene_.add_bsdf<DiffuseBSDF>(albedo);
  }

  // --- Lights ---------------------------------------------------------------

  // A CGL technique, when present, wins over technique_common; its first
  // element names the type. Area lights follow the course: in the node's
  // frame centred at the origin, emitting along -z, with edges
  // cross(up, direction) = -x and up = +y, sized by the node's transform.
  void add_light(XmlNode instance, const Mat4& world) {
    XmlNode light = doc_.resolve(instance, "url", "light");
    XmlNode technique = cgl_technique(light);
    const bool cgl = bool(technique);
    if (!cgl) technique = light.child("technique_common");
    if (!technique) doc_.fail(light, "has neither a <technique_common> nor a CGL <technique>");
    XmlNode type = first_child_element(technique);
    if (!type) doc_.fail(technique, "names no light type");
    const char* name = type.name();
    if (is(name, "spot")) return warn_once(light, "spot lights are not supported: skipped");
    if (!is(name, "area") && !is(name, "point") && !is(name, "directional") && !is(name, "ambient"))
      return warn_once(type, "unknown light type: skipped");

    XmlNode colour = type.child("color");
    if (!colour && cgl) colour = type.child("radiance");
    if (!colour) doc_.fail(type, cgl ? "missing <color> (or <radiance>)" : "missing <color>");
    const Spectrum radiance = doc_.color(colour);
    const Vec3 position = placed(instance, point(world, Vec3(0.0)), "the light");
    const Vec3 direction = placed(instance, vector(world, Vec3(0.0, 0.0, -1.0)), "the light's direction");

    if (is(name, "area")) {
      Vec3 ex = placed(instance, vector(world, Vec3(-1.0, 0.0, 0.0)), "an area light's edge");
      Vec3 ey = placed(instance, vector(world, Vec3(0.0, 1.0, 0.0)), "an area light's edge");
      Vec3 normal = glm::cross(ex, ey);
      double area = glm::length(normal);
      if (!(area > 0.0) || !std::isfinite(area))
        doc_.fail(instance, "the area light has no area: its node's transform scales it to nothing");
      // The sampled light's normal must be perpendicular to its edges; it
      // faces the side the transformed -z points to.
      normal /= area;
      if (glm::dot(normal, direction) < 0.0) normal = -normal;
      scene_.add_light<AreaLight>(radiance, position, normal, ex, ey);
      ++area_lights_;
    } else if (is(name, "point")) {
      if (type.child("constant_attenuation") || type.child("linear_attenuation") || type.child("quadratic_attenuation"))
        if (!point_attenuation_) point_attenuation_ = type;
      scene_.add_light<PointLight>(radiance, position);
    } else if (is(name, "directional")) {
      if (glm::length(direction) == 0.0)
        doc_.fail(instance, "the directional light has no direction: its node's transform scales it to nothing");
      scene_.add_light<DirectionalLight>(radiance, direction);
    } else {
      scene_.add_light<SkyLight>(radiance);  // ambient: a uniform sky
    }
  }

  // --- Camera ---------------------------------------------------------------

  // The first perspective camera: at T * origin, looking along T * -z with
  // T * y up. The fovs come from xfov and/or yfov, the missing one from
  // aspect_ratio (or the default image's 4:3 when there is none).
  void add_camera(XmlNode instance, const Mat4& world) {
    if (cameras_++ > 0) return;
    first_camera_ = instance;
    XmlNode camera = doc_.resolve(instance, "url", "camera");
    XmlNode optics = doc_.child(doc_.child(camera, "optics"), "technique_common");
    XmlNode perspective = optics.child("perspective");
    if (!perspective) {
      --cameras_;
      return warn_once(camera, "only perspective cameras are supported: skipped");
    }
    auto angle = [&](const char* name) -> std::optional<double> {
      XmlNode e = perspective.child(name);
      if (!e) return std::nullopt;
      double deg = doc_.number(e);
      if (!(deg > 0.0 && deg < 180.0)) doc_.fail(e, "expected an angle in (0, 180) degrees, got " + format_number(deg));
      return deg;
    };
    std::optional<double> xfov = angle("xfov"), yfov = angle("yfov");
    if (!xfov && !yfov) doc_.fail(perspective, "needs an <xfov> or a <yfov>");
    double aspect = double(RenderSettings{}.width) / RenderSettings{}.height;
    if (XmlNode a = perspective.child("aspect_ratio")) {
      aspect = doc_.number(a);
      if (!(aspect > 0.0)) doc_.fail(a, "expected a positive aspect ratio, got " + format_number(aspect));
    }
    auto half_tan = [](double deg) { return std::tan(glm::radians(deg) / 2.0); };
    auto from_half_tan = [](double t) { return glm::degrees(2.0 * std::atan(t)); };
    double hfov = xfov ? *xfov : from_half_tan(half_tan(*yfov) * aspect);
    double vfov = yfov ? *yfov : from_half_tan(half_tan(*xfov) / aspect);

    double near_clip = 1e-4, far_clip = 1e30;
    if (XmlNode e = perspective.child("znear")) near_clip = doc_.number(e);
    if (XmlNode e = perspective.child("zfar")) far_clip = doc_.number(e);
    if (!(near_clip > 0.0)) doc_.fail(perspective.child("znear"), "expected a positive znear");
    if (!(far_clip > near_clip)) doc_.fail(perspective, "zfar must be greater than znear");

    Vec3 position = point(world, Vec3(0.0));
    Vec3 view = vector(world, Vec3(0.0, 0.0, -1.0));
    Vec3 up = vector(world, Vec3(0.0, 1.0, 0.0));
    double cross = glm::length(glm::cross(up, view));
    const bool degenerate = !(cross > 1e-12 * glm::length(up) * glm::length(view));
    if (short_matrices_on_path_ > 0 && (degenerate || !usable(position) || !usable(view) || !usable(up))) {
      // Left so by a short <matrix>: framed as the course's viewer would frame
      // a scene without a camera, once the scene's bounds are known (load()).
      degenerate_camera_ = instance;
      scene_.camera = Camera(Vec3(0.0), Vec3(0.0, 0.0, -1.0), Vec3(0.0, 1.0, 0.0), hfov, vfov, near_clip, far_clip);
      return;
    }
    placed(instance, position, "the camera");
    placed(instance, view, "the camera's view direction");
    placed(instance, up, "the camera's up direction");
    if (degenerate) doc_.fail(instance, "the camera's node transform leaves it no view direction or no up direction");
    scene_.camera = Camera(position, position + glm::normalize(view), up, hfov, vfov, near_clip, far_clip);
  }
};

}  // namespace

void load_collada(const std::string& path, LoadedScene* out, const ColladaLimits& limits) {
  ColladaLoader(path, out, limits).load();
}

}  // namespace pt
