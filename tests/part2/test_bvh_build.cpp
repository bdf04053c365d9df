// P2T1 BVHAccel::construct_bvh: structural invariants, the inputs on which
// split methods fail, and tree quality (surface-area cost, work per ray)
// against the framework's own baseline builder (tests/support/part2_baseline.h).
// The invariants, the SAH cost and the way work is counted are defined in
// tests/support/bvh_checks.h.
#include <sstream>

#include "part2_common.h"

namespace pt::test::p2 {
namespace {

// --- Structure -----------------------------------------------------------------

GRADED_TEST(BVHStructure, InvariantsOnSoup, "P2T1", 1.5, Visible) {
  Part2Scene s = make_soup(seed(301), 3000, 150);
  for (size_t leaf : {1, 2, 4, 8}) {
    CountedBVH bvh(s.primitives(), leaf);
    expect_valid_tree(bvh, s.name);
  }
}

GRADED_TEST(BVHStructure, InvariantsOnMeshes, "P2T1", 1, Visible) {
  {
    Part2Scene s = make_mesh_scene(seed(302));
    CountedBVH bvh(s.primitives(), 4);
    expect_valid_tree(bvh, s.name);
  }
  {
    // Every box of a flat mesh has zero thickness in z.
    Part2Scene s;
    s.name = "flat grid (z = 0)";
    s.add_mesh(make_flat_grid(40, 20.0, 0.0, 0.3, seed(303)));
    CountedBVH bvh(s.primitives(), 4);
    expect_valid_tree(bvh, s.name);
  }
  {
    Part2Scene s = make_layers(seed(304), 8);
    CountedBVH bvh(s.primitives(), 3);
    expect_valid_tree(bvh, s.name);
  }
}

// --- Where split methods fail ------------------------------------------------------

// All centroids equal: no plane separates them, the mean (or median, or
// midpoint) puts everything on one side, and a builder that only recurses on
// a plane split never terminates. The handout asks for a split by count.
GRADED_TEST(BVHDegenerate, AllCentroidsEqual, "P2T1", 1.5, Visible) {
  Part2Scene s = make_copies(10000);
  auto prims = s.primitives();
  for (size_t leaf : {4, 1}) {
    CountedBVH bvh(prims, leaf);
    StructureReport rep = bvh.structure();
    EXPECT_TRUE(rep.ok()) << s.name << " (max_leaf_size " << leaf << "): " << rep.summary();
    ASSERT_LE(rep.max_depth, kMaxDepth) << s.name << " (max_leaf_size " << leaf << "): the tree is " << rep.max_depth
                                        << " levels deep (balanced: ~" << (leaf == 1 ? 14 : 12)
                                        << "): split a range whose centroids coincide by count, in halves";
    if (leaf == 4) expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 150, seed(305)), s.name);
  }
}

// All centroids on one plane: one axis has zero centroid extent (a division
// by it gives NaN bins; a mean split along it leaves one side empty). The
// other two axes must still be used: the tree must stay as good as the
// baseline's (measured: baseline 30.5-30.9, median 33.3-33.7, reference
// 29.4-29.8; a tree that falls back to halving by count when one axis fails
// costs several times more).
GRADED_TEST(BVHDegenerate, CentroidsOnOnePlane, "P2T1", 1, Hidden) {
  Part2Scene s = make_coplanar_centroids(seed(306), 4000);
  auto prims = s.primitives();
  CountedBVH bvh(prims, 4);
  if (!expect_valid_tree(bvh, s.name)) return;
  expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 1000, seed(307)), s.name);
  double student = sah_cost(bvh.tree());
  double baseline = sah_cost(build_framework_bvh(prims, 4, SplitMethod::kMeanSAH));
  EXPECT_LE(student, 1.5 * baseline) << s.name << ": SAH cost " << student << ", baseline " << baseline;
}

// One huge triangle among tiny ones: it drags the mean far from the crowd and
// puts a root-sized box into whichever child receives it.
GRADED_TEST(BVHDegenerate, HugeTriangleAmongTiny, "P2T1", 1, Hidden) {
  Part2Scene s = make_huge_among_tiny(seed(308), 4000);
  auto prims = s.primitives();
  CountedBVH bvh(prims, 4);
  if (!expect_valid_tree(bvh, s.name)) return;
  expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 1000, seed(309)), s.name);
}

GRADED_TEST(BVHDegenerate, SinglePrimitiveAndEmptyScene, "P2T1", 0.5, Visible) {
  {
    Part2Scene s;
    s.name = "a single sphere";
    s.add_sphere(Vec3(0.5, -0.25, 1.0), 0.75);
    CountedBVH bvh(s.primitives(), 4);
    expect_valid_tree(bvh, s.name);
    EXPECT_EQ(bvh.tree().nodes.size(), 1u) << s.name << ": the root should be a leaf";
    expect_agrees_with_linear_scan(bvh, s.primitives(), make_rays(s, 300, seed(310)), s.name);
  }
  {
    Part2Scene s;
    s.name = "a single triangle, max_leaf_size 1";
    s.add_triangle(Vec3(-1, 0, 0), Vec3(1, 0.5, 0.25), Vec3(0, 1, -0.5));
    CountedBVH bvh(s.primitives(), 1);
    expect_valid_tree(bvh, s.name);
    expect_agrees_with_linear_scan(bvh, s.primitives(), make_rays(s, 300, seed(311)), s.name);
  }
  {
    // No primitives: BVHAccel does not call construct_bvh; queries miss.
    CountedBVH bvh({}, 4);
    EXPECT_TRUE(bvh.structure().ok()) << bvh.structure().summary();
    EXPECT_TRUE(bvh.bvh().get_bbox().empty());
    Ray r(Vec3(0.0), Vec3(0, 0, 1));
    Intersection isect;
    EXPECT_FALSE(bvh.closest(r, &isect)) << "empty scene, ray " << r;
    EXPECT_FALSE(bvh.any(r)) << "empty scene, ray " << r;
  }
}

// --- Quality -----------------------------------------------------------------------
//
// SAH cost of the student's tree (max_leaf_size 4) against the framework's
// baseline builder (three axes, candidate at the mean centroid, surface-area
// cost: the handout's method) on the same primitives. The factors rest on the
// costs measured by tests/part2/test_bvh_calibration.cpp over seed offsets 0
// to 10 (ranges over those seeds; ratios to the baseline of the same scene):
//
//               baseline   3 axes + SAH at:        reference  longest axis only, at:        x axis
//               cost       median     midpoint     (binned)   midpoint   mean   equal counts  only
//   mesh        40.8-40.9  1.07       1.01-1.02    0.98       1.05-1.06  1.06   1.18          28
//   clustered   7.3-8.4    1.76-2.21  0.79-0.91    0.83-1.00  0.77-0.94  0.96-1.09 2.21-2.58  8-25
//   elongated   128-131    1.14-1.16  0.98-1.00    0.95-0.96  5.16-5.24  5.28-5.37 6.08-6.23  16
//   coplanar    30.5-30.9  1.08-1.10  0.99-1.00    0.96-0.97  1.00-1.01  1.01-1.02 1.11-1.12  6.4
//   (bunny, 3.7k triangles, when present: baseline 27.9, median 1.06, reference 0.94, longest-axis midpoint 1.06)
//
// A single-axis split (longest axis of the centroid box, at the midpoint, the
// mean or equal counts) is as good as the baseline on meshes and clustered
// scenes, but on the elongated one (fibres 400 units long, spread 200 along
// their length and 8 across) the longest centroid axis is the fibres' own
// axis: every child keeps their full length, and the cost is 5.2x to 6.2x.
// The elongated factor 2.0 lies between the worst method the handout accepts
// (median + SAH, 1.16: a 1.7x margin) and the best single-axis split (5.16:
// a 2.6x margin). The other factors only catch broken or one-axis trees:
// mesh 1.5 (x axis only: 28x), clustered 3.0 (lets the median split pass,
// which cuts dense clumps in half there: up to 2.21x), coplanar 1.5 (in
// BVHDegenerate). A correct implementation of the baseline measures 1.0 to
// within a few percent whatever its tie-breaking or centroid definition.

void expect_cost_within(const Part2Scene& s, double factor) {
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

GRADED_TEST(BVHQuality, SahCostOnMesh, "P2T1", 1, Visible) { expect_cost_within(make_mesh_scene(seed(320)), 1.5); }

GRADED_TEST(BVHQuality, SahCostOnClusteredScene, "P2T1", 0.5, Hidden) {
  expect_cost_within(make_clustered(seed(321)), 3.0);
}

GRADED_TEST(BVHQuality, SahCostOnElongatedScene, "P2T1", 1.5, Visible) {
  expect_cost_within(make_fibres(seed(322), 4096), 2.0);
}

// Average primitive tests and node visits per closest-hit ray on the mesh,
// the student's build and traversal against the baseline tree walked by the
// framework's ordered traversal (how nodes are counted: bvh_checks.h). A
// linear scan makes 20,528 tests per ray.
// Measured (3000 rays, seed offsets 0 to 10), tests / nodes per ray:
// baseline 3.86-4.05 / 9.65-10.08; reference 3.81-4.05 / 9.48-9.92;
// median + SAH 4.02-4.27 / 10.2-10.7; longest-axis equal counts 4.42-4.68 /
// 11.5-12.0; x axis only 133-154 / 148-167. Traversal bugs (reference tree):
// no ordering 7.2 tests (1.8x), far child first 11.3 (2.8x), no pruning
// 11.4 (2.9x). Bound: 1.5x the baseline, +1 test and +2 nodes for
// small-number noise: every reasonable tree passes with a margin of 1.4x or
// more; traversal order is tested properly in BVHTraversal.
GRADED_TEST(BVHQuality, WorkPerRayOnMesh, "P2T1", 1, Hidden) {
  Part2Scene s = make_mesh_scene(seed(323));
  auto prims = s.primitives();
  auto rays = make_rays(s, 3000, seed(324));
  CountedBVH bvh(prims, 4);
  ASSERT_TRUE(bvh.structure().ok()) << bvh.structure().summary();
  WorkTotals student;
  for (const Ray& ray : rays) {
    Ray r = ray;
    Intersection isect;
    QueryWork w;
    bvh.closest(r, &isect, &w);
    student.add(w);
  }
  WorkMeter meter(prims);
  FlatTree base = build_framework_bvh(meter.wrapped(), 4, SplitMethod::kMeanSAH);
  meter.attach(base);
  WorkTotals baseline = framework_work(meter, base, rays);
  testing::Test::RecordProperty("tests_per_ray", std::to_string(student.tests()));
  testing::Test::RecordProperty("nodes_per_ray", std::to_string(student.nodes()));
  EXPECT_LE(student.tests(), 1.5 * baseline.tests() + 1.0)
      << s.name << ": your BVH makes " << student.tests() << " primitive tests per ray; the baseline "
      << baseline.tests() << " (a linear scan: " << prims.size() << ")";
  EXPECT_LE(student.nodes(), 1.5 * baseline.nodes() + 2.0)
      << s.name << ": your BVH reaches " << student.nodes() << " nodes per ray; the baseline " << baseline.nodes();
}

}  // namespace
}  // namespace pt::test::p2
