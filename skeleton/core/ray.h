#pragma once
#include "core/vec.h"

namespace pt {

// A ray o + t d restricted to t in [min_t, max_t]. max_t is mutable because a
// closest-hit query shrinks it as nearer hits are found, even through a const
// reference: that is how later tests prune farther primitives.
struct Ray {
  Vec3 o{0.0};
  Vec3 d{0.0, 0.0, -1.0};
  mutable double min_t = 0.0;
  mutable double max_t = kInf;
  int depth = 0;  // remaining bounces for the global-illumination estimator

  Ray() = default;
  Ray(const Vec3& origin, const Vec3& direction, double max_t_ = kInf, int depth_ = 0)
      : o(origin), d(direction), max_t(max_t_), depth(depth_) {}

  Vec3 at(double t) const { return o + t * d; }
};

inline std::ostream& operator<<(std::ostream& os, const Ray& r) {
  return os << "[o=" << r.o << " d=" << r.d << " t in [" << r.min_t << ", " << r.max_t << "]]";
}

}  // namespace pt
