#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "geometry/bvh.h"
#include "geometry/mesh.h"
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "scene/light.h"

namespace pt {

// Everything a render needs: owns materials, meshes, primitives and lights,
// and answers ray queries through a BVH over all primitives.
class Scene {
 public:
  Scene() = default;
  Scene(Scene&&) = default;
  Scene& operator=(Scene&&) = default;

  // Ownership helpers for builders; each returns the stored object.
  template <class B, class... Args>
  const B* add_bsdf(Args&&... args) {
    touch();
    bsdfs.push_back(std::make_unique<B>(std::forward<Args>(args)...));
    return static_cast<const B*>(bsdfs.back().get());
  }
  template <class L, class... Args>
  const L* add_light(Args&&... args) {
    touch();
    lights.push_back(std::make_unique<L>(std::forward<Args>(args)...));
    const L* light = static_cast<const L*>(lights.back().get());
    // Summed here once, so that escaping rays need not search the lights.
    if constexpr (std::is_base_of_v<SkyLight, L>) sky_radiance_ += light->radiance;
    return light;
  }
  // Adds the mesh and one Triangle per face.
  const Mesh* add_mesh(Mesh mesh);
  void add_sphere(const Vec3& center, double radius, const BSDF* bsdf);
  // A parallelogram (two triangles) centred at `center` with edges ex, ey;
  // its normal is normalize(cross(ex, ey)).
  const Mesh* add_quad(const Vec3& center, const Vec3& ex, const Vec3& ey, const BSDF* bsdf);
  // An area light together with the emitting quad that camera rays can see.
  // A non-zero albedo makes the quad reflect too (a glowing diffuse wall).
  void add_area_light(const Spectrum& radiance, const Vec3& center, const Vec3& ex, const Vec3& ey,
                      const Spectrum& albedo = Spectrum(0.0));

  // Builds the BVH; call after the last shape is added.
  void build(size_t max_leaf_size = 4);

  // Queries (counted in work_counters().rays).
  bool intersect(const Ray& r, Intersection* isect) const;
  bool has_intersection(const Ray& r) const;

  // Radiance arriving along a ray that leaves the scene (sky lights).
  Spectrum background(const Vec3& /*dir*/) const { return sky_radiance_; }

  size_t triangle_count() const;

  // A number no other scene had and that changes with every function above
  // that adds or builds, so that what was derived from a scene (the grader's
  // copy of it in another process, autograder/boundary/) can be told from
  // what a changed or a different scene needs. Assigning to the members
  // below directly does not change it.
  uint64_t revision() const { return revision_; }
  // The union of the primitives' boxes (not the BVH's: no BVH is needed, and
  // a student's BVH cannot move it).
  BBox bounds() const;

  Camera camera;
  std::vector<std::unique_ptr<BSDF>> bsdfs;
  std::vector<std::unique_ptr<Mesh>> meshes;
  std::vector<std::unique_ptr<Primitive>> primitives;
  std::vector<std::unique_ptr<Light>> lights;
  std::unique_ptr<BVHAccel> bvh;

 private:
  static uint64_t next_revision();
  void touch() { revision_ = next_revision(); }

  Spectrum sky_radiance_{0.0};  // sum of the SkyLights added with add_light
  uint64_t revision_ = next_revision();
};

}  // namespace pt
