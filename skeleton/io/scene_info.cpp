#include "io/scene_info.h"

#include <nlohmann/json.hpp>

#include "geometry/sphere.h"

namespace pt {

namespace {

nlohmann::json array(const Vec3& v) { return {v.x, v.y, v.z}; }

bool emits(const BSDF* bsdf) { return bsdf && bsdf->get_emission(Vec3(0.0, 0.0, 1.0)) != Spectrum(0.0); }

template <class L>
int count(const Scene& s) {
  int n = 0;
  for (const auto& l : s.lights) n += dynamic_cast<const L*>(l.get()) != nullptr;
  return n;
}

}  // namespace

std::string scene_info_json(const LoadedScene& loaded) {
  const Scene& s = loaded.scene;
  size_t spheres = 0, emissive = 0;
  for (const auto& p : s.primitives)
    if (dynamic_cast<const Sphere*>(p.get())) ++spheres, emissive += emits(p->get_bsdf());
  for (const auto& m : s.meshes) emissive += emits(m->bsdf);

  nlohmann::json j;
  j["triangles"] = s.triangle_count();
  j["spheres"] = spheres;
  j["meshes"] = s.meshes.size();
  j["lights"] = {{"area", count<AreaLight>(s)},
                 {"point", count<PointLight>(s)},
                 {"directional", count<DirectionalLight>(s)},
                 {"sky", count<SkyLight>(s)}};
  j["emissive_shapes"] = emissive;
  j["camera"] = {{"position", array(s.camera.pos)},
                 {"direction", array(-s.camera.c2w[2])},
                 {"hfov", s.camera.hfov},
                 {"vfov", s.camera.vfov}};
  BBox b = s.bounds();
  j["bounds"] = b.empty() ? nlohmann::json(nullptr) : nlohmann::json{{"min", array(b.min)}, {"max", array(b.max)}};
  j["warnings"] = loaded.warnings;
  // Warnings quote file content and paths, which need not be UTF-8.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace pt
