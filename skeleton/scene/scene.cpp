#include "scene/scene.h"

#include <atomic>

#include "core/stats.h"
#include "geometry/counted.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace pt {

uint64_t Scene::next_revision() {
  static std::atomic<uint64_t> last{0};
  return ++last;
}

const Mesh* Scene::add_mesh(Mesh mesh) {
  touch();
  if (mesh.normals.size() != mesh.positions.size()) mesh.compute_vertex_normals();
  meshes.push_back(std::make_unique<Mesh>(std::move(mesh)));
  const Mesh* m = meshes.back().get();
  for (const auto& f : m->faces) primitives.push_back(std::make_unique<Counted<Triangle>>(m, f[0], f[1], f[2]));
  return m;
}

void Scene::add_sphere(const Vec3& center, double radius, const BSDF* bsdf) {
  touch();
  primitives.push_back(std::make_unique<Counted<Sphere>>(center, radius, bsdf));
}

const Mesh* Scene::add_quad(const Vec3& c, const Vec3& ex, const Vec3& ey, const BSDF* bsdf) {
  Mesh m;
  m.name = "quad";
  Vec3 hx = 0.5 * ex, hy = 0.5 * ey;
  m.positions = {c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy};
  Vec3 n = glm::normalize(glm::cross(ex, ey));
  m.normals.assign(4, n);
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  m.bsdf = bsdf;
  return add_mesh(std::move(m));
}

void Scene::add_area_light(const Spectrum& radiance, const Vec3& center, const Vec3& ex, const Vec3& ey,
                           const Spectrum& albedo) {
  Vec3 n = glm::normalize(glm::cross(ex, ey));
  add_light<AreaLight>(radiance, center, n, ex, ey);
  const BSDF* bsdf = albedo == Spectrum(0.0) ? static_cast<const BSDF*>(add_bsdf<EmissionBSDF>(radiance))
                                             : add_bsdf<DiffuseBSDF>(albedo, radiance);
  add_quad(center, ex, ey, bsdf);
}

void Scene::build(size_t max_leaf_size) {
  touch();
  std::vector<Primitive*> prims;
  prims.reserve(primitives.size());
  for (auto& p : primitives) prims.push_back(p.get());
  bvh = std::make_unique<BVHAccel>(std::move(prims), max_leaf_size);
}

bool Scene::intersect(const Ray& r, Intersection* isect) const {
  ++work_counters().rays;
  return bvh->intersect(r, isect);
}

bool Scene::has_intersection(const Ray& r) const {
  ++work_counters().rays;
  return bvh->has_intersection(r);
}

size_t Scene::triangle_count() const {
  size_t n = 0;
  for (const auto& m : meshes) n += m->faces.size();
  return n;
}

BBox Scene::bounds() const {
  BBox b;
  for (const auto& p : primitives) b.expand(p->get_bbox());
  return b;
}

}  // namespace pt
