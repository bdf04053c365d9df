// Hostile: the tests count a traversal's work by the primitive tests they see
// (tests/support/bvh_checks.h). Across the process boundary the worker once
// wrapped copies of the real triangles and spheres, whose intersect writes
// `isect->primitive = this`: a build that fires probe rays at each primitive
// got the shape behind the wrapper back in the hit record, and a traversal
// could then test the shapes themselves, unseen. This build probes every
// primitive through its box and keeps, for each, the Triangle or Sphere a hit
// names; the closest-hit query then scans every primitive, linearly, testing
// the recovered shapes directly and only the rest through the primitive it was
// given (those whose box the ray enters). The worker now holds handles (autograder/boundary/bvh_worker.cpp): a
// hit names the handle, no shape is recovered, and every test of the scan is a
// call back to the verifier, counted there: the scan loses what a scan of
// every box the ray enters loses (no pruning, no order), and nothing more. (The probes run at the first query of each tree,
// so that one edit of the reference makes the attack.)
#include <unordered_map>
#include <vector>

#include "geometry/bbox.h"
#include "geometry/intersection.h"
#include "geometry/primitive.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace {
// Each primitive the build was given -> the shape a probe ray found behind it.
std::unordered_map<const pt::Primitive*, const pt::Primitive*>& recovered() {
  static std::unordered_map<const pt::Primitive*, const pt::Primitive*> shapes;
  return shapes;
}

bool is_shape(const pt::Primitive* p) {
  return dynamic_cast<const pt::Triangle*>(p) != nullptr || dynamic_cast<const pt::Sphere*>(p) != nullptr;
}

// Rays along each axis through a 3 x 3 grid of the box's cross-section, until
// one hits. After 16 hits that name the primitive itself (no shape behind it),
// probing stops: there is nothing to recover.
void probe(const std::vector<pt::Primitive*>& prims) {
  int named_itself = 0;
  for (const pt::Primitive* p : prims) {
    recovered()[p] = nullptr;
    if (named_itself >= 16) continue;
    const pt::BBox b = p->get_bbox();
    const pt::Vec3 size = b.max - b.min;
    bool found = false;
    for (int axis = 0; axis < 3 && !found; ++axis)
      for (int i = 1; i <= 3 && !found; ++i)
        for (int j = 1; j <= 3 && !found; ++j) {
          pt::Vec3 o = b.min + size * 0.5, d(0.0);
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          o[u] = b.min[u] + size[u] * i / 4.0;
          o[v] = b.min[v] + size[v] * j / 4.0;
          o[axis] = b.min[axis] - 1.0;
          d[axis] = 1.0;
          pt::Intersection isect;
          if (!p->intersect(pt::Ray(o, d), &isect)) continue;
          found = true;
          if (isect.primitive != p && is_shape(isect.primitive)) {
            recovered()[p] = isect.primitive;
          } else {
            ++named_itself;
          }
        }
  }
}

// Which tree each accelerator was probed for: its root and first primitive.
struct Probed {
  const void* root;
  const pt::Primitive* first;
};

bool scan_closest(const void* accel, const void* root, const std::vector<pt::Primitive*>& prims, const pt::Ray& r,
                  pt::Intersection* isect) {
  static std::unordered_map<const void*, Probed> probed;
  const Probed now{root, prims.empty() ? nullptr : prims.front()};
  const auto found = probed.find(accel);
  if (found == probed.end() || found->second.root != now.root || found->second.first != now.first) {
    probe(prims);
    probed[accel] = now;
  }
  bool hit = false;
  for (const pt::Primitive* p : prims) {
    const auto found = recovered().find(p);
    const pt::Primitive* shape = found == recovered().end() ? nullptr : found->second;
    if (const auto* t = dynamic_cast<const pt::Triangle*>(shape)) {
      hit = t->pt::Triangle::intersect(r, isect) || hit;  // unseen by any wrapper
    } else if (const auto* s = dynamic_cast<const pt::Sphere*>(shape)) {
      hit = s->pt::Sphere::intersect(r, isect) || hit;
    } else {
      double t0 = r.min_t, t1 = r.max_t;  // no tree: every primitive whose box the ray enters
      if (p->get_bbox().intersect(r, t0, t1)) hit = p->intersect(r, isect) || hit;
    }
  }
  return hit;
}
}  // namespace
