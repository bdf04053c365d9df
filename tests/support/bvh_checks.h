#pragma once
// Framework-side BVH checks for the Part 2 tests. Nothing here calls the
// student's BBox::intersect or traversal: the checker reads the tree
// (BVHAccel::root(), BVHAccel::primitives()) and recomputes what it needs with
// its own code, so that a bug in one task cannot hide a bug in another.
//
//  * flatten() copies a BVHNode tree into arrays (iteratively: a degenerate
//    tree thousands of levels deep must not overflow the checker's stack).
//  * check_structure() verifies the structural invariants listed below.
//  * sah_cost() is the surface-area cost of a tree.
//  * CountedBVH builds the student's BVHAccel over counting decorators and
//    measures the work of each query (see "Counting work" below).
//  * framework_closest() is an ordered, pruned closest-hit traversal used as
//    the yardstick for the student's traversal work, on the same tree.
//  * child_order_violations() checks, from the leaves a query entered and
//    their order, that a closest-hit traversal went into the nearer child
//    (by entry distance) first.
//
// Structural invariants (check_structure):
//  1. A root exists exactly when there are primitives.
//  2. primitives() is a permutation of the input (nothing lost or duplicated).
//  3. Every node owns a non-empty range [start, end) inside the array; the
//     root owns [0, N).
//  4. Every interior node has two children whose ranges are adjacent, do not
//     overlap and together make up the parent's range exactly ("no empty
//     child"; either child may come first).
//  5. Hence, and also checked directly, every primitive index lies in exactly
//     one leaf.
//  6. Every box is tight: it contains the union of the boxes of its
//     primitives and exceeds it by no more than 1e-9 x max(1, largest
//     coordinate of the scene) on any side (the union of min/max is exact in
//     floating point, so a correct build matches to the last bit; the slack
//     only forgives a deliberate epsilon padding).
//  7. Every box lies inside its parent's box (same tolerance).
//  8. Leaf size: every leaf holds at most max(1, max_leaf_size) primitives.
//     "Unless it cannot be split" is taken literally: any range of two or more
//     primitives CAN be split, by count if no plane separates the centroids
//     (that is what the handout asks for when all centroids coincide), so the
//     only leaf that may exceed max_leaf_size is a single primitive when
//     max_leaf_size is 0. A leaf of everything when the centroids coincide
//     (pbrt's choice) is therefore reported as a violation.
//  9. Depth (root = 0) is reported; the tests bound it.
//
// SAH cost (sah_cost): with A the surface area of the TIGHT box of a node
// (recomputed from its primitives, so that an untight box cannot lower it),
//   cost = sum over interior nodes  A(n) / A(root) * kCostTraversal
//        + sum over leaves          A(n) / A(root) * count(n) * kCostIntersect
// with kCostTraversal = kCostIntersect = 1: the expected number of node visits
// plus primitive tests of a random line that hits the root box (for lines
// uniformly distributed in space, P(hit child | hit parent) = area ratio),
// counting an interior node (two child box tests) as much as one primitive
// test. If A(root) = 0 (all primitives are points or lie on a segment) every
// ratio is taken as 1.
//
// Counting work (CountedBVH): the student's traversal and box test are the
// student's code, so the framework cannot instrument node visits directly
// (BBox::intersect is not virtual and is compiled into the student's part).
// What it can see is every primitive test: each primitive is wrapped, before
// the BVH is built, in a CountingPrimitive that forwards to the real one and
// logs (primitive, result). From that log, and from which leaf owns each
// primitive in the built tree, each query reports:
//  * primitive_tests: exactly the calls to has_intersection/intersect;
//  * leaves: the number of distinct leaves in which a primitive was tested
//    (every leaf is non-empty, so entering a leaf means testing at least one
//    of its primitives: this is exactly the leaves entered);
//  * nodes: the number of distinct nodes on the root-to-leaf paths of those
//    leaves: the interior nodes a traversal must have descended through to
//    reach them, plus the leaves. It is a lower bound on the node boxes a
//    traversal enters (an interior node entered without reaching any leaf
//    below it is not seen); a top-down traversal tests about twice as many
//    boxes (both children of each interior node entered).
// The same log, read the same way, measures the framework's own traversal on
// the same tree, so that the student's work is compared like with like.
// The counters of core/stats.h are never read: a student's code need not bump them.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/bvh.h"
#include "geometry/counted.h"

namespace pt::test::part2 {

constexpr double kCostTraversal = 1.0;
constexpr double kCostIntersect = 1.0;

struct FlatNode {
  BBox bb;  // as stored in the tree
  size_t start = 0, end = 0;
  int left = -1, right = -1, parent = -1;
  int depth = 0;
  bool leaf() const { return left < 0 && right < 0; }
  size_t size() const { return end > start ? end - start : 0; }
};

// A BVH as arrays: nodes[0] is the root (no nodes when there is no root);
// `prims` is the primitive array the node ranges index.
struct FlatTree {
  std::vector<FlatNode> nodes;
  std::vector<const Primitive*> prims;
  int max_depth() const;
  size_t leaf_count() const;
};

FlatTree flatten(const BVHAccel& bvh);

struct StructureReport {
  size_t nodes = 0, leaves = 0, largest_leaf = 0;
  int max_depth = 0;
  size_t violation_count = 0;
  std::vector<std::string> violations;  // the first few, in words
  bool ok() const { return violation_count == 0; }
  std::string summary() const;  // statistics and the violations, for a failure message
};

// `input`: the primitives given to the builder, in any order.
StructureReport check_structure(const FlatTree& tree, const std::vector<const Primitive*>& input,
                                size_t max_leaf_size);

// Tight boxes of every node, recomputed from the primitives (bottom-up where
// the children tile the parent, directly from the range otherwise).
std::vector<BBox> tight_boxes(const FlatTree& tree);
double sah_cost(const FlatTree& tree);

// The framework's slab test: a closed box; a zero direction component keeps
// the slab when the origin lies within [min, max] (planes included) and
// rejects it otherwise; divisions rather than reciprocals. Narrows [t0, t1].
bool slab_closed(const BBox& b, const Ray& r, double& t0, double& t1);

// Ordered (nearer child first, by box entry), pruned (skips a node whose entry
// lies beyond the current r.max_t) closest hit over `tree`.
bool framework_closest(const FlatTree& tree, const Ray& r, Intersection* isect);

// Closest hit and any hit by testing every primitive in order.
bool linear_closest(const std::vector<const Primitive*>& prims, const Ray& r, Intersection* isect);
bool linear_any(const std::vector<const Primitive*>& prims, const Ray& r);

// --- Counting --------------------------------------------------------------
struct TestEvent {
  size_t index;  // the primitive's position in the input
  bool hit;
};

class CountingPrimitive : public ForwardingPrimitive {
 public:
  CountingPrimitive(const Primitive* inner, size_t index, std::vector<TestEvent>* log)
      : inner_(inner), index_(index), log_(log) {}
  BBox get_bbox() const override { return inner_->get_bbox(); }
  const BSDF* get_bsdf() const override { return inner_->get_bsdf(); }
  bool has_intersection(const Ray& r) const override {
    bool h = inner_->has_intersection(r);
    log_->push_back({index_, h});
    return h;
  }
  bool intersect(const Ray& r, Intersection* isect) const override {
    bool h = inner_->intersect(r, isect);
    log_->push_back({index_, h});
    return h;
  }
  const Primitive& wrapped() const override { return *inner_; }
  const Primitive* inner() const { return inner_; }
  size_t index() const { return index_; }

 private:
  const Primitive* inner_;
  size_t index_;
  std::vector<TestEvent>* log_;
};

struct QueryWork {
  size_t primitive_tests = 0;
  size_t leaves = 0;
  size_t nodes = 0;
  size_t tests_after_first_hit = 0;  // primitive tests made after one reported a hit
  QueryWork& operator+=(const QueryWork& o);
};

// Work summed over many queries, with per-ray averages.
struct WorkTotals {
  QueryWork sum;
  size_t queries = 0;
  void add(const QueryWork& w) {
    sum += w;
    ++queries;
  }
  double tests() const { return queries ? double(sum.primitive_tests) / queries : 0.0; }
  double leaves() const { return queries ? double(sum.leaves) / queries : 0.0; }
  double nodes() const { return queries ? double(sum.nodes) / queries : 0.0; }
};
std::ostream& operator<<(std::ostream& os, const WorkTotals& w);

// Wraps primitives in CountingPrimitives and turns the log of one query into
// QueryWork, given the tree whose leaves own the wrapped primitives.
class WorkMeter {
 public:
  explicit WorkMeter(const std::vector<const Primitive*>& prims);
  WorkMeter(const WorkMeter&) = delete;
  WorkMeter& operator=(const WorkMeter&) = delete;
  // The wrappers, in input order.
  const std::vector<const Primitive*>& wrapped() const { return wrapped_; }
  // Records which leaf of `tree` owns each wrapper (tree.prims are wrappers).
  void attach(const FlatTree& tree);
  void start() const { log_.clear(); }
  // The work of the query since start(); with `leaves_in_order`, also the
  // leaves it entered, in the order of their first primitive test.
  QueryWork stop(std::vector<int>* leaves_in_order = nullptr) const;
  const Primitive* unwrap(const Primitive* p) const;

 private:
  std::vector<std::unique_ptr<CountingPrimitive>> wrappers_;
  std::vector<const Primitive*> wrapped_;
  mutable std::vector<TestEvent> log_;
  const FlatTree* tree_ = nullptr;
  std::vector<int> leaf_of_;  // input index -> leaf node (-1: in no leaf)
  mutable std::vector<uint32_t> mark_;
  mutable uint32_t stamp_ = 0;
};

// The framework traversal's work on a framework-built tree over the wrappers
// of `meter` (build with build_framework_bvh(meter.wrapped(), ...)).
WorkTotals framework_work(const WorkMeter& meter, const FlatTree& tree, const std::vector<Ray>& rays);

// The student's BVHAccel built over counting wrappers of `prims`.
class CountedBVH {
 public:
  CountedBVH(const std::vector<const Primitive*>& prims, size_t max_leaf_size = 4);
  ~CountedBVH();

  const BVHAccel& bvh() const { return *bvh_; }
  const FlatTree& tree() const { return tree_; }
  size_t max_leaf_size() const { return max_leaf_size_; }
  StructureReport structure() const { return check_structure(tree_, meter_.wrapped(), max_leaf_size_); }

  // The student's closest hit on `r` (r.max_t shrinks as the contract says).
  // isect->primitive is reported as the original (unwrapped) primitive.
  bool closest(const Ray& r, Intersection* isect, QueryWork* work = nullptr,
               std::vector<int>* leaves_in_order = nullptr) const;
  // The student's any-hit query.
  bool any(const Ray& r, QueryWork* work = nullptr) const;
  // The framework's ordered, pruned traversal of the same tree.
  bool reference_closest(const Ray& r, Intersection* isect, QueryWork* work = nullptr) const;

 private:
  size_t max_leaf_size_;
  WorkMeter meter_;
  std::unique_ptr<BVHAccel> bvh_;
  FlatTree tree_;
};

// --- The order of a closest-hit traversal -----------------------------------
// A closest-hit traversal visits the child whose box the ray enters first
// (the smaller entry t0 on [r.min_t, r.max_t]) before the other. A depth-first
// traversal, recursive or with a stack, finishes the subtree of the child it
// goes into before it starts the other's, so the first leaf entered below
// the nearer child comes before the first leaf entered below the farther one.
// child_order_violations() reads that off the leaves a query entered (in the
// order of their first primitive test, WorkMeter::stop): every interior node
// with leaves entered below both children whose boxes (as stored in the tree)
// the ray enters more than 1e-9 (relative, at least 1e-9 absolute) apart is
// checked (`checked`, if given, counts them); children entered at the same
// distance may go in either order. A node whose farther child was pruned has
// leaves below one child only and is not checked.
struct OrderViolation {
  int node = -1;
  int went_first = -1, nearer = -1;  // child nodes: the one entered first by the query, the one the ray enters first
  double went_first_t0 = 0.0, nearer_t0 = 0.0;  // where the ray enters their boxes
};
std::vector<OrderViolation> child_order_violations(const FlatTree& tree, const Ray& r,
                                                   const std::vector<int>& leaves_in_order, int* checked = nullptr);

// --- Comparing hits ----------------------------------------------------------
// Whether a BVH closest-hit result matches the linear scan of the same ray
// (`ray` is the ray as it was before either query). Exact agreement of the hit
// flag is required; the hit distance must agree to 1e-9 (relative), and the
// reported primitive must be the scan's or, when two primitives are hit at
// (almost) the same t (a shared edge, identical copies), one whose own hit
// distance on the ray is that t. On a hit, isect->t must equal the ray's
// shrunk max_t when `bvh_max_t` is given.
testing::AssertionResult same_closest_hit(const Ray& ray, bool bvh_hit, const Intersection& bvh,
                                          bool scan_hit, const Intersection& scan, const double* bvh_max_t = nullptr);

// One line describing a primitive (triangle vertices or sphere), for messages.
std::string describe(const Primitive* p);

}  // namespace pt::test::part2
