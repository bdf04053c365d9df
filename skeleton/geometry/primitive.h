#pragma once
#include "core/ray.h"
#include "geometry/bbox.h"
#include "geometry/intersection.h"

namespace pt {

class BSDF;

// Anything a ray can hit. Both queries respect [r.min_t, r.max_t]; intersect()
// additionally shrinks r.max_t to the hit so that farther hits are rejected.
class Primitive {
 public:
  virtual ~Primitive() = default;
  virtual BBox get_bbox() const = 0;
  virtual bool has_intersection(const Ray& r) const = 0;
  virtual bool intersect(const Ray& r, Intersection* isect) const = 0;
  virtual const BSDF* get_bsdf() const = 0;
};

}  // namespace pt
