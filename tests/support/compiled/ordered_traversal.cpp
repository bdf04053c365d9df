// The framework's own slab test and ordered, pruned closest-hit traversal
// (declared in support/bvh_checks.h): the yardsticks the Part 2 tests measure
// a student's box test and traversal against. They are near-solutions to P2T2
// and P2T3, so the student release ships this file compiled only
// (tests/support/compiled/: see tools/release/README.md).
#include <algorithm>
#include <vector>

#include "support/bvh_checks.h"

namespace pt::test::part2 {

bool slab_closed(const BBox& b, const Ray& r, double& t0, double& t1) {
  for (int a = 0; a < 3; ++a) {
    if (r.d[a] == 0.0) {
      if (r.o[a] < b.min[a] || r.o[a] > b.max[a]) return false;
      continue;
    }
    double tn = (b.min[a] - r.o[a]) / r.d[a];
    double tf = (b.max[a] - r.o[a]) / r.d[a];
    if (tn > tf) std::swap(tn, tf);
    t0 = std::max(t0, tn);
    t1 = std::min(t1, tf);
    if (t0 > t1) return false;
  }
  return true;
}

bool framework_closest(const FlatTree& t, const Ray& r, Intersection* isect) {
  if (t.nodes.empty()) return false;
  double t0 = r.min_t, t1 = r.max_t;
  if (!slab_closed(t.nodes[0].bb, r, t0, t1)) return false;
  struct Item {
    int node;
    double entry;
  };
  std::vector<Item> stack{{0, t0}};
  bool hit = false;
  while (!stack.empty()) {
    Item it = stack.back();
    stack.pop_back();
    if (it.entry > r.max_t) continue;  // pruned: a nearer hit was found since it was pushed
    const FlatNode& n = t.nodes[size_t(it.node)];
    if (n.leaf()) {
      for (size_t i = n.start; i < n.end && i < t.prims.size(); ++i) hit |= t.prims[i]->intersect(r, isect);
      continue;
    }
    Item near{-1, 0.0}, far{-1, 0.0};
    for (int c : {n.left, n.right}) {
      if (c < 0) continue;
      double c0 = r.min_t, c1 = r.max_t;
      if (!slab_closed(t.nodes[size_t(c)].bb, r, c0, c1)) continue;
      Item ci{c, c0};
      if (near.node < 0) {
        near = ci;
      } else if (ci.entry < near.entry) {
        far = near;
        near = ci;
      } else {
        far = ci;
      }
    }
    if (far.node >= 0) stack.push_back(far);
    if (near.node >= 0) stack.push_back(near);
  }
  return hit;
}

}  // namespace pt::test::part2
