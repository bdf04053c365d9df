#pragma once
// Primitive tests counted by the framework, around the call into Part 1's
// intersection code, so that every build (a student's BVH included, which
// counts nothing itself) reports its real work per ray. The scene wraps every
// triangle and sphere it owns in Counted<>; tests that build primitives by
// hand use the plain classes.
#include "core/stats.h"
#include "geometry/primitive.h"

namespace pt {

template <class P>
class Counted final : public P {
 public:
  using P::P;
  bool has_intersection(const Ray& r) const override {
    ++work_counters().primitive_tests;
    return P::has_intersection(r);
  }
  bool intersect(const Ray& r, Intersection* isect) const override {
    ++work_counters().primitive_tests;
    return P::intersect(r, isect);
  }
};

}  // namespace pt
