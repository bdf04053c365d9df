#pragma once
// Helpers shared by the Part 2 test files.
#include <string>
#include <vector>

#include "core/rng.h"
#include "support/bvh_checks.h"
#include "support/graded.h"
#include "support/part2_baseline.h"
#include "support/part2_scenes.h"
#include "support/seed.h"

namespace pt::test::part2 {

// Depth bound for every Part 2 scene (up to ~21,000 primitives, leaves of 1
// to 8). A balanced tree over 20,000 primitives has depth 13 to 15; the
// framework's builders and the reference measure 10 to 19 on these scenes.
// Any split that sends at least a fixed fraction of the primitives to each
// side stays logarithmic (even a lopsided 1:4 split stays below 40 here);
// peeling one primitive per level, a classic way to "guarantee progress" on
// equal centroids, goes thousands of levels deep.
constexpr int kMaxDepth = 64;

// At most this many mismatches are reported per scene; the rest are counted.
constexpr int kMaxReported = 5;

// Checks the student's closest hit (and, if `any_hit`, its any-hit query)
// against linear scans of the same primitives, ray by ray. Every failure
// streams the ray and both answers.
inline void expect_agrees_with_linear_scan(const CountedBVH& bvh, const std::vector<const Primitive*>& prims,
                                           const std::vector<Ray>& rays, const std::string& what,
                                           bool closest_hit = true, bool any_hit = true) {
  int reported = 0, mismatches = 0, hits = 0;
  for (const Ray& ray : rays) {
    Ray scan_ray = ray;
    Intersection scan;
    bool scan_hit = linear_closest(prims, scan_ray, &scan);
    hits += scan_hit;
    bool ok = true;
    if (closest_hit) {
      Ray r = ray;
      Intersection isect;
      bool hit = bvh.closest(r, &isect);
      testing::AssertionResult res = same_closest_hit(ray, hit, isect, scan_hit, scan, &r.max_t);
      if (!res) {
        ok = false;
        if (reported < kMaxReported) ADD_FAILURE() << what << ", closest hit (BVHAccel::intersect):\n" << res.message();
      }
    }
    if (any_hit) {
      bool hit = bvh.any(ray);
      if (hit != scan_hit) {
        ok = false;
        if (reported < kMaxReported)
          ADD_FAILURE() << what << ", any hit (BVHAccel::has_intersection):\nray " << ray << "\nreturned "
                        << (hit ? "true" : "false") << " but the linear scan "
                        << (scan_hit ? "hits " + describe(scan.primitive) + " at t = " + std::to_string(scan.t)
                                     : std::string("hits nothing"));
      }
    }
    if (!ok) {
      ++mismatches;
      ++reported;
    }
  }
  EXPECT_EQ(mismatches, 0) << what << ": " << mismatches << " of " << rays.size() << " rays disagree with the linear scan";
  // The ray sets are built so that a good share hit: guards the test itself.
  EXPECT_GE(hits, int(rays.size()) / 10) << what << ": too few rays hit anything for this test to mean much";
}

// The structural invariants of bvh_checks.h, and the depth bound. Returns
// whether the tree is within the depth bound, so that a test can stop before
// it traverses a tree deep enough to overflow a recursive traversal.
inline bool expect_valid_tree(const CountedBVH& bvh, const std::string& what) {
  StructureReport rep = bvh.structure();
  EXPECT_TRUE(rep.ok()) << what << " (max_leaf_size " << bvh.max_leaf_size() << "): " << rep.summary();
  EXPECT_LE(rep.max_depth, kMaxDepth) << what << ": the tree is " << rep.max_depth << " levels deep, more than "
                                      << kMaxDepth << ": " << rep.summary();
  return rep.max_depth <= kMaxDepth;
}

// Axis-aligned geometry hit by axis-parallel rays whose origins lie exactly
// on the planes of leaf boxes: the slab test sees 0 * inf there (see the
// handout), and a NaN that turns into a miss loses real hits. The zero
// components are `zero` (+0.0 or -0.0).
inline std::vector<Ray> grid_aligned_rays(int n, uint64_t s, double zero = 0.0) {
  Rng rng(s, 41);
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    double line = double(int(31 * rng.uniform()) - 15);  // a grid line, exactly
    double along = 30 * rng.uniform() - 15;
    double slope = rng.uniform() - 0.5;
    switch (i % 4) {
      case 0: rays.emplace_back(Vec3(line, along, 5.0), Vec3(zero, slope, -1.0)); break;
      case 1: rays.emplace_back(Vec3(along, line, -5.0), Vec3(slope, zero, 1.0)); break;
      case 2: rays.emplace_back(Vec3(line, along, 3.0), Vec3(zero, zero, -1.0)); break;
      default: rays.emplace_back(Vec3(line + 0.5, line, 2.0), Vec3(zero, zero, -0.5)); break;
    }
  }
  return rays;
}

// The SAH cost (bvh_checks.h) of the student's tree, max_leaf_size 4, within
// `factor` of the framework's baseline builder (three axes, candidate at the
// mean centroid, surface-area cost: the handout's method) on the same
// primitives. The factors rest on the costs that test_bvh_calibration.cpp
// prints; a correct implementation of the baseline measures 1.0 to within a
// few percent whatever its tie-breaking or centroid definition.
inline void expect_cost_within(const Part2Scene& s, double factor) {
  auto prims = s.primitives();
  CountedBVH bvh(prims, 4);
  StructureReport rep = bvh.structure();
  ASSERT_TRUE(rep.ok()) << s.name << ": the SAH cost is only measured on a valid tree: " << rep.summary();
  double student = sah_cost(bvh.tree());
  double baseline = sah_cost(build_framework_bvh(prims, 4, SplitMethod::kMeanSAH));
  double midpoint = sah_cost(build_framework_bvh(prims, 4, SplitMethod::kMidpointLongest));
  testing::Test::RecordProperty("sah_cost", std::to_string(student));
  testing::Test::RecordProperty("sah_cost_baseline", std::to_string(baseline));
  EXPECT_LE(student, factor * baseline)
      << s.name << " (" << s.size() << " primitives, max_leaf_size 4): SAH cost of your tree " << student
      << " = " << student / baseline << " x the baseline's " << baseline << "; allowed: " << factor
      << " x. (For comparison, a longest-axis midpoint split costs " << midpoint
      << "; see bvh_checks.h for the cost's definition.)";
}

}  // namespace pt::test::part2
