#pragma once
#include "core/vec.h"

namespace pt {

// An orthonormal basis whose z axis is a surface normal. BSDFs work in this
// local frame, where cos(theta) of a direction is just its z component.
struct Frame {
  Vec3 s, t, n;

  // Duff et al. 2017, "Building an Orthonormal Basis, Revisited": branch-free
  // and continuous everywhere but n.z = -1, where the sign switch handles it.
  static Frame from_normal(const Vec3& n) {
    double sign = std::copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double b = n.x * n.y * a;
    return {Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y), n};
  }
  Vec3 to_local(const Vec3& w) const { return {glm::dot(w, s), glm::dot(w, t), glm::dot(w, n)}; }
  Vec3 to_world(const Vec3& w) const { return w.x * s + w.y * t + w.z * n; }
};

}  // namespace pt
