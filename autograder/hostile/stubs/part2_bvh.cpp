// Part 2's stubs as the release ships them, without their comments: the base
// of the hostile cases that are an attack in an otherwise untouched submission
// (README.md beside this folder). Frozen here so that a case never changes
// when tasks/, the student's file, does.
#include "core/not_implemented.h"
#include "core/stats.h"
#include "geometry/bvh.h"

namespace pt {

std::unique_ptr<BVHNode> BVHAccel::construct_bvh(PrimIter start, PrimIter end, size_t max_leaf_size) {
  throw NotImplemented("P2T1 BVHAccel::construct_bvh");
}

bool BBox::intersect(const Ray& r, double& t0, double& t1) const {
  throw NotImplemented("P2T2 BBox::intersect");
}

bool BVHAccel::has_intersection(const Ray& r, const BVHNode* node) const {
  throw NotImplemented("P2T3 BVHAccel::has_intersection");
}

bool BVHAccel::intersect(const Ray& r, Intersection* isect, const BVHNode* node) const {
  throw NotImplemented("P2T3 BVHAccel::intersect");
}

}  // namespace pt
