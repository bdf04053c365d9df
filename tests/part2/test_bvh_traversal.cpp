// P2T3 BVHAccel::intersect and BVHAccel::has_intersection: agreement with a
// linear scan over every primitive on thousands of seeded rays, and the work
// of the traversal (ordered, pruned; any-hit stops at
// the first hit), counted as described in tests/support/bvh_checks.h.
// Triangle and Sphere intersection are the reference's here (Part 1).
#include <iomanip>

#include "core/rng.h"
#include "part2_common.h"

namespace pt::test::p2 {
namespace {

GRADED_TEST(BVHCorrectness, ClosestHitMatchesLinearScanOnSoup, "P2T3", 2, Visible) {
  Part2Scene s = make_soup(seed(401), 4000, 200);
  auto prims = s.primitives();
  {
    CountedBVH bvh(prims, 4);
    expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 3000, seed(402)), s.name + ", max_leaf_size 4", true,
                                   false);
  }
  {
    CountedBVH bvh(prims, 1);
    expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 1000, seed(403)), s.name + ", max_leaf_size 1", true,
                                   false);
  }
}

// Rays along the coordinate axes from random points.
std::vector<Ray> axis_rays(const Part2Scene& s, int n, uint64_t sd) {
  Rng rng(sd, 42);
  BBox b = s.bounds();
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    Vec3 o = b.min + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * b.extent();
    Vec3 d(0.0);
    d[i % 3] = (i / 3) % 2 ? 1.0 : -1.0;
    o[i % 3] = b.centroid()[i % 3] - 2.0 * d[i % 3] * b.extent()[i % 3];  // start outside, pointing in
    rays.emplace_back(o, d);
  }
  return rays;
}

GRADED_TEST(BVHCorrectness, ClosestHitMatchesLinearScanOnMeshes, "P2T3", 2, Visible) {
  {
    Part2Scene s = make_mesh_scene(seed(404));
    auto prims = s.primitives();
    CountedBVH bvh(prims, 4);
    expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 2000, seed(405)), s.name, true, false);
    expect_agrees_with_linear_scan(bvh, prims, axis_rays(s, 300, seed(406)), s.name + ", axis-parallel rays", true,
                                   false);
  }
  {
    Part2Scene s;
    s.name = "flat jittered grid (every box has zero thickness in z)";
    s.add_mesh(make_flat_grid(40, 20.0, 0.0, 0.3, seed(407)));
    auto prims = s.primitives();
    CountedBVH bvh(prims, 4);
    expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 1000, seed(408)), s.name, true, false);
  }
  {
    Part2Scene s;
    s.name = "axis-aligned unit grid in z = 0, rays with origins on grid lines";
    s.add_mesh(make_flat_grid(32, 32.0, 0.0, 0.0, 0));
    auto prims = s.primitives();
    CountedBVH bvh(prims, 4);
    expect_agrees_with_linear_scan(bvh, prims, grid_aligned_rays(600, seed(409)), s.name, true, false);
  }
}

GRADED_TEST(BVHCorrectness, AnyHitAgreesWithLinearScan, "P2T3", 1, Visible) {
  {
    Part2Scene s = make_soup(seed(410), 4000, 200);
    auto prims = s.primitives();
    CountedBVH bvh(prims, 4);
    expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 3000, seed(411)), s.name, false, true);
  }
  {
    Part2Scene s = make_mesh_scene(seed(412));
    auto prims = s.primitives();
    CountedBVH bvh(prims, 4);
    expect_agrees_with_linear_scan(bvh, prims, make_rays(s, 1000, seed(413)), s.name, false, true);
  }
  {
    Part2Scene s;
    s.name = "axis-aligned unit grid in z = 0, rays with origins on grid lines";
    s.add_mesh(make_flat_grid(32, 32.0, 0.0, 0.0, 0));
    auto prims = s.primitives();
    CountedBVH bvh(prims, 4);
    expect_agrees_with_linear_scan(bvh, prims, grid_aligned_rays(600, seed(414)), s.name, false, true);
  }
}

// --- Traversal work -------------------------------------------------------------------
//
// Sixteen stacked sheets, rays roughly along +z or -z (half each): a ray
// crosses every sheet, so a traversal that does not visit the nearer child
// first, or does not skip boxes that start beyond the current max_t, tests
// the triangles of many sheets instead of one. The student's traversal is
// compared with the framework's ordered, pruned traversal ON THE STUDENT'S
// OWN TREE, so the tree's quality does not enter.
//
// Measured (2000 rays, seed offsets 0 to 10): the reference traversal and
// the framework's (an explicit stack, children ordered by box entry) make the
// same 4.02-4.04 primitive tests, 1.01 leaves and 12.0 nodes per ray. The
// traversal bugs of the mutant gallery (seed offset 0), as ratios to the
// framework traversal (primitive tests / nodes): far child first, no pruning
// by max_t, or testing a copy of the ray: 16x / 6.5x (64.9 tests, 78 nodes);
// no ordering (left child first), or a slab test that does not narrow
// [t0, t1] so that entries cannot be compared: 8.2x / 3.6x (33.1 tests,
// 43.5 nodes). Bound: 1.5x (+0.5 tests, +1 node): a correct ordered
// traversal measures 1.0x, the mildest bug 8x.
GRADED_TEST(BVHTraversal, NearerChildFirstAndPruned, "P2T3", 1.5, Visible) {
  Part2Scene s = make_layers(seed(417), 16);
  auto prims = s.primitives();
  CountedBVH bvh(prims, 4);
  ASSERT_TRUE(bvh.structure().ok()) << bvh.structure().summary();
  WorkTotals student, framework;
  int reported = 0;
  for (const Ray& ray : make_layer_rays(s, 2000, seed(418))) {
    Ray r1 = ray, r2 = ray;
    Intersection i1, i2;
    QueryWork w1, w2;
    bool h1 = bvh.closest(r1, &i1, &w1);
    bool h2 = bvh.reference_closest(r2, &i2, &w2);
    student.add(w1);
    framework.add(w2);
    if (reported < kMaxReported) {
      testing::AssertionResult same = same_closest_hit(ray, h1, i1, h2, i2);
      if (!same) {
        ++reported;
        ADD_FAILURE() << s.name << ", closest hit differs from an ordered traversal of your tree:\n" << same.message();
      }
    }
  }
  testing::Test::RecordProperty("tests_per_ray", std::to_string(student.tests()));
  // GoogleTest prints doubles at 17 digits (33.100000000000001), in its
  // EXPECT_LE and in a message alike: averages of counts need 4.
  EXPECT_TRUE(student.tests() <= 1.5 * framework.tests() + 0.5)
      << std::setprecision(4) << s.name << ": your closest-hit traversal makes " << student.tests()
      << " primitive tests per ray; an ordered traversal with pruning by max_t on the same tree makes "
      << framework.tests() << ". Visit the child whose box the ray enters first, and skip a box whose entry t lies "
      << "beyond r.max_t.\n  yours:     " << student << "\n  framework: " << framework;
  EXPECT_TRUE(student.nodes() <= 1.5 * framework.nodes() + 1.0)
      << std::setprecision(4) << s.name << ": your traversal reaches " << student.nodes() << " nodes per ray, the ordered one "
      << framework.nodes();
}

// any-hit may stop at the first hit found, and must: a shadow ray needs no
// more. Checked exactly: after a primitive test reports a hit, the query makes
// no further primitive test (on the stacked sheets, where the ray would
// otherwise go on through fifteen more sheets).
GRADED_TEST(BVHTraversal, AnyHitStopsAtFirstHit, "P2T3", 1, Visible) {
  Part2Scene s = make_layers(seed(419), 16);
  auto prims = s.primitives();
  CountedBVH bvh(prims, 4);
  WorkTotals any, closest;
  int late = 0, wrong = 0, reported = 0;
  for (const Ray& ray : make_layer_rays(s, 1000, seed(420))) {
    QueryWork w;
    bool hit = bvh.any(ray, &w);
    any.add(w);
    bool expect = linear_any(prims, ray);
    if (hit != expect) {
      ++wrong;
      if (reported++ < kMaxReported)
        ADD_FAILURE() << s.name << ": ray " << ray << "\nhas_intersection returned " << hit << ", expected " << expect;
    }
    if (w.tests_after_first_hit > 0) {
      ++late;
      if (reported++ < kMaxReported)
        ADD_FAILURE() << s.name << ": ray " << ray << "\nhas_intersection went on with " << w.tests_after_first_hit
                      << " more primitive test(s) after one had reported a hit (" << w.primitive_tests
                      << " in all); return at the first hit";
    }
    Ray r = ray;
    Intersection isect;
    bvh.closest(r, &isect, &w);
    closest.add(w);
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(late, 0) << "rays on which any-hit did not stop at the first hit; any-hit: " << any
                     << "; closest-hit: " << closest;
}

}  // namespace
}  // namespace pt::test::p2
