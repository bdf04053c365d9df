#pragma once
#include "geometry/mesh.h"
#include "geometry/primitive.h"

namespace pt {

// One face of a Mesh.
class Triangle : public Primitive {
 public:
  Triangle(const Mesh* mesh, uint32_t v1, uint32_t v2, uint32_t v3) : mesh_(mesh), v1_(v1), v2_(v2), v3_(v3) {}

  BBox get_bbox() const override;
  const BSDF* get_bsdf() const override { return mesh_->bsdf; }

  const Vec3& p1() const { return mesh_->positions[v1_]; }
  const Vec3& p2() const { return mesh_->positions[v2_]; }
  const Vec3& p3() const { return mesh_->positions[v3_]; }
  const Vec3& n1() const { return mesh_->normals[v1_]; }
  const Vec3& n2() const { return mesh_->normals[v2_]; }
  const Vec3& n3() const { return mesh_->normals[v3_]; }

  // P1T3: Moller-Trumbore. Hit only for t in [r.min_t, r.max_t].
  bool has_intersection(const Ray& r) const override;
  // P1T3: as above; on a hit also shrink r.max_t and fill isect (t, normal
  // interpolated from n1..n3 with the barycentrics, barycentrics, primitive,
  // bsdf).
  bool intersect(const Ray& r, Intersection* isect) const override;

 private:
  const Mesh* mesh_;
  uint32_t v1_, v2_, v3_;
};

}  // namespace pt
