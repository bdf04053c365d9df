#pragma once
#include "geometry/primitive.h"

namespace pt {

class Sphere : public Primitive {
 public:
  Sphere(const Vec3& center, double radius, const BSDF* bsdf) : o(center), r(radius), r2(radius * radius), bsdf_(bsdf) {}

  BBox get_bbox() const override { return BBox(o - Vec3(r), o + Vec3(r)); }
  const BSDF* get_bsdf() const override { return bsdf_; }

  // P1T4: solve |o + t d - c|^2 = r^2. Returns whether real roots exist and
  // writes them with t1 <= t2 (whatever the ray's t range).
  bool test(const Ray& ray, double& t1, double& t2) const;
  // P1T4: hit if a root lies in [min_t, max_t] (the nearer one when both do).
  bool has_intersection(const Ray& ray) const override;
  // P1T4: as above; shrink ray.max_t, fill isect with the outward unit normal.
  bool intersect(const Ray& ray, Intersection* isect) const override;

  Vec3 o;     // centre
  double r;   // radius
  double r2;  // radius squared

 private:
  const BSDF* bsdf_;
};

}  // namespace pt
