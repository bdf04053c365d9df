// Part 2: the bounding volume hierarchy. See handouts/part2.md.
#include "core/not_implemented.h"
#include "core/stats.h"
#include "geometry/bvh.h"

namespace pt {

std::unique_ptr<BVHNode> BVHAccel::construct_bvh(PrimIter start, PrimIter end, size_t max_leaf_size) {
  // TODO(P2T1): box the primitives in [start, end); make a leaf (node->start,
  // node->end are indices into primitives_) when there are at most
  // max_leaf_size of them; otherwise choose the split with the lowest
  // surface-area cost over the three axes, std::partition the range and
  // recurse. Make sure both sides are non-empty, even when all centroids are equal.
  throw NotImplemented("P2T1 BVHAccel::construct_bvh");
}

bool BBox::intersect(const Ray& r, double& t0, double& t1) const {
  // TODO(P2T2): slab test; narrow [t0, t1] to the part inside the box and
  // return whether it is non-empty. Direction components may be zero.
  throw NotImplemented("P2T2 BBox::intersect");
}

bool BVHAccel::has_intersection(const Ray& r, const BVHNode* node) const {
  // TODO(P2T3): any hit in the subtree; you may return at the first one.
  throw NotImplemented("P2T3 BVHAccel::has_intersection");
}

bool BVHAccel::intersect(const Ray& r, Intersection* isect, const BVHNode* node) const {
  // TODO(P2T3): closest hit in the subtree. Visit the nearer child first and
  // skip a child whose box starts beyond r.max_t.
  throw NotImplemented("P2T3 BVHAccel::intersect");
}

}  // namespace pt
