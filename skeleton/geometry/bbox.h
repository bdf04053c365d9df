#pragma once
#include <algorithm>

#include "core/ray.h"

namespace pt {

// Axis-aligned bounding box. An empty box has min = +inf and max = -inf so
// that expanding it by anything yields that thing.
struct BBox {
  Vec3 min{kInf};
  Vec3 max{-kInf};

  BBox() = default;
  explicit BBox(const Vec3& p) : min(p), max(p) {}
  BBox(const Vec3& a, const Vec3& b) : min(glm::min(a, b)), max(glm::max(a, b)) {}

  void expand(const Vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void expand(const BBox& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  Vec3 extent() const { return max - min; }
  Vec3 centroid() const { return 0.5 * (min + max); }
  double surface_area() const {
    if (empty()) return 0.0;
    Vec3 e = extent();
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  int longest_axis() const {
    Vec3 e = extent();
    return e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  }
  bool contains(const BBox& b) const {
    return b.empty() || (glm::all(glm::lessThanEqual(min, b.min)) && glm::all(glm::greaterThanEqual(max, b.max)));
  }

  // P2T2: ray-box slab test. On entry [t0, t1] is the ray's current interval;
  // on a hit it is narrowed to the part of the ray inside the box and true is
  // returned. Must handle direction components equal to zero.
  bool intersect(const Ray& r, double& t0, double& t1) const;
};

inline std::ostream& operator<<(std::ostream& os, const BBox& b) { return os << "[" << b.min << " - " << b.max << "]"; }

}  // namespace pt
