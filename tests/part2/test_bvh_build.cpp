// P2T1 BVHAccel::construct_bvh: structural invariants, the inputs on which
// split methods fail, and tree quality (surface-area cost)
// against the framework's own baseline builder (tests/support/part2_baseline.h).
// The invariants, the SAH cost and the way work is counted are defined in
// tests/support/bvh_checks.h.
#include <sstream>

#include "common.h"

namespace pt::test::part2 {
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
// SAH cost of the student's tree against the baseline's (expect_cost_within,
// part2/common.h). Measured over seed offsets 0 to 10 (ranges over those
// seeds; ratios to the baseline of the same scene):
//
//               baseline   3 axes + SAH at:        reference  longest axis only, at:        x axis
//               cost       median     midpoint     (binned)   midpoint   mean   equal counts  only
//   mesh        40.8-40.9  1.07       1.01-1.02    0.98       1.05-1.06  1.06   1.18          28
//   elongated   128-131    1.14-1.16  0.98-1.00    0.95-0.96  5.16-5.24  5.28-5.37 6.08-6.23  16
//   (bunny, 3.7k triangles, when present: baseline 27.9, median 1.06, reference 0.94, longest-axis midpoint 1.06)
//
// A single-axis split (longest axis of the centroid box, at the midpoint, the
// mean or equal counts) is as good as the baseline on meshes, but on the
// elongated scene (fibres 400 units long, spread 200 along their length and
// 8 across) the longest centroid axis is the fibres' own axis: every child
// keeps their full length, and the cost is 5.2x to 6.2x. The elongated
// factor 2.0 lies between the worst method the handout accepts (median +
// SAH, 1.16: a 1.7x margin) and the best single-axis split (5.16: a 2.6x
// margin). The mesh factor 1.5 only catches broken or one-axis trees (x axis
// only: 28x).

GRADED_TEST(BVHQuality, SahCostOnMesh, "P2T1", 1, Visible) { expect_cost_within(make_mesh_scene(seed(320)), 1.5); }

GRADED_TEST(BVHQuality, SahCostOnElongatedScene, "P2T1", 1.5, Visible) {
  expect_cost_within(make_fibres(seed(322), 4096), 2.0);
}

// A single flat mesh, finely subdivided: a 64 x 64 grid of quads (8192
// triangles, vertices jittered in x and y by up to 0.3 of a cell) in the
// plane z = 0, so that every box has zero thickness and zero volume. The
// surface area of a flat box is twice its area in the plane, and the SAH
// compares splits here as well as anywhere. A cost built on the boxes'
// volumes (1.10-1.24x the baseline on the torus mesh at seed offset 0,
// inside SahCostOnMesh's 1.5) makes every candidate cost 0 here, and
// whichever candidate the loop meets first or last wins at every level: the
// first bin on x (a binned build), one primitive against the rest (a sweep),
// x or y alone at the mean (the baseline's candidates). Measured over seed offsets 0 to 10, ratios to the
// baseline's cost (17.6-17.7): median + SAH 1.000, midpoint + SAH 1.000,
// binned SAH (the reference) 0.999-1.000, sweep SAH 0.997-1.000,
// longest-axis midpoint 1.014-1.015; volume cost with the baseline's
// candidates 6.19-6.36, binned 7.15-7.32, sweep 236 (8188 levels deep);
// x axis only 6.2-6.4. Factor 2.5: 2.46x above every surface-area method
// measured, 2.48x below the mildest volume cost.
GRADED_TEST(BVHQuality, SahCostOnFlatPlane, "P2T1", 1, Visible) {
  Part2Scene s;
  s.name = "flat jittered 64 x 64 grid in z = 0 (every box has zero volume)";
  s.add_mesh(make_flat_grid(64, 20.0, 0.0, 0.3, seed(325)));
  expect_cost_within(s, 2.5);
}

// One triangle 2,000 units across among 4,000 tiny ones (edges ~0.02) in
// [-10, 10]^3. Every candidate split puts the huge box on one side, so what
// a split costs there hangs on the other side's box: a cost that lets
// anything of one candidate's evaluation into another's (a binned sweep
// whose left box is not reset after the right-to-left sweep, so that every
// left side costs the whole node's area) builds a tree 39 levels deep at
// 3.3x the baseline's cost. Measured over seed offsets 0 to 2, ratios to the
// baseline (11.9-12.9): median + SAH 1.00-1.17, midpoint + SAH 1.00-1.16,
// single-axis splits 0.99-1.17, x axis only 1.03-1.10, binned SAH (the
// reference) 0.39-0.69 (seed offsets 0 to 19); the unreset left box
// 3.06-3.91 (seed offsets 0 to 9). Factor 2: 1.7x above the worst accepted
// method, 1.5x below that bug.
GRADED_TEST(BVHQuality, SahCostWithOneHugeTriangle, "P2T1", 0.5, Visible) {
  expect_cost_within(make_huge_among_tiny(seed(327), 4000), 2.0);
}

}  // namespace
}  // namespace pt::test::part2
