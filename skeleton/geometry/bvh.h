#pragma once
#include <memory>
#include <vector>

#include "core/stats.h"
#include "geometry/primitive.h"

namespace pt {

// The box of a BVH node: a BBox whose intersect() counts one node visit and
// then runs BBox::intersect (P2T2). The framework counts the work of every
// traversal this way, a student's included, as long as it tests node->bb.
struct NodeBox : BBox {
  NodeBox() = default;
  NodeBox(const BBox& b) : BBox(b) {}  // NOLINT: implicit, so that `node->bb = box` works
  bool intersect(const Ray& r, double& t0, double& t1) const {
    ++work_counters().node_visits;
    return BBox::intersect(r, t0, t1);
  }
};

// A node owns the primitives [start, end) of the accelerator's primitive
// array; a leaf has no children.
struct BVHNode {
  NodeBox bb;
  size_t start = 0, end = 0;
  std::unique_ptr<BVHNode> l, r;

  bool is_leaf() const { return !l && !r; }
  size_t size() const { return end - start; }
};

class BVHAccel : public Primitive {
 public:
  using PrimIter = std::vector<Primitive*>::iterator;

  // Builds the hierarchy over `primitives` (not owned) with construct_bvh.
  BVHAccel(std::vector<Primitive*> primitives, size_t max_leaf_size = 4);
  ~BVHAccel() override;

  BBox get_bbox() const override { return root_ ? root_->bb : BBox(); }
  const BSDF* get_bsdf() const override { return nullptr; }

  // P2T1: build the subtree over [start, end), reordering that range in place
  // so that every node's primitives are contiguous. Leaves hold at most
  // max_leaf_size primitives unless they cannot be split.
  std::unique_ptr<BVHNode> construct_bvh(PrimIter start, PrimIter end, size_t max_leaf_size);

  // P2T3: any hit in [r.min_t, r.max_t] (may stop at the first one found).
  bool has_intersection(const Ray& r) const override { return root_ && has_intersection(r, root_.get()); }
  bool has_intersection(const Ray& r, const BVHNode* node) const;
  // P2T3: closest hit; visit the nearer child first, prune by r.max_t.
  bool intersect(const Ray& r, Intersection* isect) const override { return root_ && intersect(r, isect, root_.get()); }
  bool intersect(const Ray& r, Intersection* isect, const BVHNode* node) const;

  const BVHNode* root() const { return root_.get(); }
  const std::vector<Primitive*>& primitives() const { return primitives_; }

 private:
  std::vector<Primitive*> primitives_;
  std::unique_ptr<BVHNode> root_;
};

}  // namespace pt
