// Hostile: the tests count a traversal's work by the primitive tests they see
// (tests/support/bvh_checks.h); across the process boundary each is a call
// back to the verifier (autograder/boundary/bvh_worker.cpp). This closest-hit
// query tests every primitive, linearly, and hides the work: it casts each
// primitive to the Triangle or Sphere it hopes lies behind it and calls that
// class's own intersect, which no counter sees. The primitives it is given
// are the tests' counting wrappers in one process and the worker's handles
// (a box and an index, no geometry) across the boundary, not triangles, so it
// finds nothing to call and says so: every test that asks for a closest hit
// fails with that message, and no hidden work is credited.
#include <stdexcept>
#include <vector>

#include "geometry/intersection.h"
#include "geometry/primitive.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace {
bool unseen_closest(const std::vector<pt::Primitive*>& prims, const pt::Ray& r, pt::Intersection* isect) {
  bool hit = false;
  for (const pt::Primitive* p : prims) {
    if (const auto* t = dynamic_cast<const pt::Triangle*>(p)) {
      hit = t->pt::Triangle::intersect(r, isect) || hit;
    } else if (const auto* s = dynamic_cast<const pt::Sphere*>(p)) {
      hit = s->pt::Sphere::intersect(r, isect) || hit;
    } else {
      throw std::runtime_error("unseen scan: a primitive that is no Triangle or Sphere; nothing to test unseen");
    }
  }
  return hit;
}
}  // namespace
