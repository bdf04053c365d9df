#pragma once
// An Intersection across the boundary. Its pointers mean nothing in the other
// process, so each crosses as what it points at: nothing, the primitive being
// asked (or its BSDF), or something else, which the receiving side maps to
// its own objects.
#include "geometry/intersection.h"
#include "geometry/primitive.h"
#include "geometry/sphere.h"
#include "scene/bsdf.h"
#include "wire.h"

namespace pt::boundary {

enum class Points : uint8_t { Nothing = 0, Asked = 1, Elsewhere = 2 };

// What a hit's "something else" becomes on a side that has no such object
// of its own: objects nobody else made, so that no test's object equals them.
inline const Primitive* elsewhere_primitive() {
  static const Sphere s(Vec3(0.0), 0.0, nullptr);
  return &s;
}
inline const BSDF* elsewhere_bsdf() {
  static const DiffuseBSDF b{Spectrum(0.0)};
  return &b;
}

struct HitSide {
  const Primitive* asked;            // the primitive whose intersect() is called
  const Primitive* elsewhere;        // what "something else" becomes on this side
  const BSDF* asked_bsdf;            // asked->get_bsdf()
  const BSDF* elsewhere_bsdf;
};

inline void put_hit(Writer& w, const Intersection& h, const HitSide& side) {
  auto token = [](const void* p, const void* asked) {
    return p == nullptr ? Points::Nothing : p == asked ? Points::Asked : Points::Elsewhere;
  };
  w.put(h.t).put(h.n).put(h.barycentric).put(token(h.primitive, side.asked)).put(token(h.bsdf, side.asked_bsdf));
}

inline void get_hit(Reader& r, Intersection& h, const HitSide& side) {
  r.get(h.t);
  r.get(h.n);
  r.get(h.barycentric);
  const auto primitive = r.get<Points>(), bsdf = r.get<Points>();
  h.primitive = primitive == Points::Nothing ? nullptr : primitive == Points::Asked ? side.asked : side.elsewhere;
  h.bsdf = bsdf == Points::Nothing ? nullptr : bsdf == Points::Asked ? side.asked_bsdf : side.elsewhere_bsdf;
}

}  // namespace pt::boundary
