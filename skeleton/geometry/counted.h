#pragma once
// Primitive tests counted around the call into Part 1's intersection code.
// Counted<> is the framework's: every build (a student's BVH included, which
// counts nothing itself) reports its real work per ray; the scene wraps every
// triangle and sphere it owns in it, and tests that build primitives by hand
// use the plain classes. ForwardingPrimitive is how the tests' own counting
// primitives (which log each test) say what they wrap.
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

// A primitive that stands in for another and forwards its tests to it: what
// it hits is the wrapped primitive (whose intersect() writes itself into the
// hit record). Code that handles a primitive by what it is (the grader's
// process boundary, which sends shapes to another process) looks through it.
class ForwardingPrimitive : public Primitive {
 public:
  virtual const Primitive& wrapped() const = 0;
};

}  // namespace pt
