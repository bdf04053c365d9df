#pragma once
// "From the reference to Embree, one step at a time" for pt-bench.
//
// Each step is an accelerator built from the reference BVH's own tree (the
// same splits, the same leaves) that adds one engineering step to the step
// before it, so that the table shows what each step buys on the same rays in
// the same run:
//
//   1. flat          the tree copied into one array of 64-byte nodes
//                    (double box, indices; siblings adjacent), traversed
//                    exactly like the reference: the "compact flattened
//                    layout" on its own
//   2. float pairs   a 64-byte node holds both children's boxes in float,
//                    rounded outwards: one cache line answers "which children
//                    does the ray enter?"
//   3. + triangles   the leaves' triangles copied in leaf order (three
//                    vertices, double): no virtual call, no index into the
//                    mesh, the same arithmetic as Part 1's reference
//                    (watertight) triangle test
//   4. 4-wide        the binary tree collapsed into nodes of four children,
//                    their boxes tested at once with SSE (float, widened so as
//                    never to miss what the double test hits)
//   5. + float triangles   each leaf's triangles in packets of four, tested at
//                    once with SSE in float (Embree's "triangle4" leaves),
//                    by Moller-Trumbore: not watertight
//
// Steps 1 to 4 find exactly the reference's hits (the same t to the bit);
// step 5 computes in float and agrees to float precision, as Embree does.
// Steps 3 to 5 bypass Part 1's Triangle::intersect: that is exactly what the
// reference may not do (a student's Part 1 must decide every hit in a
// renderer built with the reference BVH), and why these steps live here.
// Instructor-only: every step is a complete traversal, i.e. a solution of
// P2T3 in another form; strip this file pair from a student release.
#include <memory>
#include <string>
#include <vector>

#include "geometry/bvh.h"

namespace pt::bench::ladder {

class Step {
 public:
  virtual ~Step() = default;
  virtual std::string name() const = 0;  // a column header
  // Closest hit: the t of the nearest hit in [r.min_t, r.max_t], or kInf.
  virtual double closest(const Ray& r) const = 0;
  // Whether anything is hit in [r.min_t, r.max_t].
  virtual bool any(const Ray& r) const = 0;
  virtual size_t bytes() const = 0;  // nodes and copied primitives
  // Whether the answers equal the reference's to the bit (else: to float precision).
  virtual bool exact() const { return true; }
};

// The steps for the tree of `bvh`, in order. Steps 3 to 5 need every
// primitive to be a Triangle; otherwise they are left out and *note says so.
std::vector<std::unique_ptr<Step>> make_steps(const BVHAccel& bvh, std::string* note);

// One line per step: what it adds.
std::vector<std::string> step_descriptions();

}  // namespace pt::bench::ladder
