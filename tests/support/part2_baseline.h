#pragma once
// Framework-side BVH builders for the Part 2 quality tests. The part 2 test
// binary links the student's builder, not the reference one, so the yardstick
// for tree quality is built here, independently of both:
//
//  * kMeanSAH, the handout's baseline: at each node, one candidate plane per
//    axis at the mean of the primitives' box centroids; the candidate with the
//    lowest  area(left box) x count(left) + area(right box) x count(right)
//    wins (candidates leaving a side empty are skipped); when none is left
//    (all centroids coincide), the range is halved by count.
//  * kMedianSAH: the same with the candidate at the median centroid per axis
//    (the other split point the handout discusses; must pass the thresholds).
//  * kMidpointLongest: the classic single-axis split, at the middle of the
//    centroid box along its longest axis, no cost model (must FAIL them).
//  * kMidpointSAH: three axes, candidates at the middle of the centroid box,
//    surface-area cost (another reasonable method; must pass).
//  * kMeanLongest, kObjectMedianLongest (equal counts along the longest axis),
//    kMidpointX: further single-axis variants, for calibration.
//
// Every builder makes leaves of at most max(1, max_leaf_size) primitives, as
// the structural checker requires.
#include <vector>

#include "support/bvh_checks.h"

namespace pt::test::part2 {

enum class SplitMethod { kMeanSAH, kMedianSAH, kMidpointSAH, kMidpointLongest, kMeanLongest, kObjectMedianLongest, kMidpointX };
const char* method_name(SplitMethod m);

FlatTree build_framework_bvh(std::vector<const Primitive*> prims, size_t max_leaf_size, SplitMethod method);

}  // namespace pt::test::part2
