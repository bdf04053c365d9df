// P2T3 BVHAccel::intersect and BVHAccel::has_intersection: agreement with a
// linear scan over every primitive on thousands of seeded rays, limited ray
// intervals, and the work of the traversal (ordered, pruned; any-hit stops at
// the first hit), counted as described in tests/support/bvh_checks.h.
// Triangle and Sphere intersection are the reference's here (Part 1).
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

// Axis-aligned geometry hit by axis-parallel rays whose origins lie exactly
// on the planes of leaf boxes: the slab test sees 0 * inf there (see the
// handout), and a NaN that turns into a miss loses real hits. The zero
// components are +0.0 (see BVHPending below for -0.0).
std::vector<Ray> grid_aligned_rays(int n, uint64_t s, double zero = 0.0) {
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

// Rays whose [min_t, max_t] cuts the scene: the nearest hit at or after
// min_t and at or before max_t must be found, and nothing outside reported.
// For each ray whose first hit is at t*: max_t = t*/2 (nothing there),
// max_t = t* exactly (the hit counts: the interval is closed), min_t just
// past t* (the next surface behind), min_t = t*/2, and max_t = 1.5 t*.
// Rays that hit nothing get max_t = 5.
GRADED_TEST(BVHCorrectness, LimitedRayInterval, "P2T3", 1, Hidden) {
  Part2Scene s = make_soup(seed(415), 3000, 150);
  auto prims = s.primitives();
  CountedBVH bvh(prims, 4);
  std::vector<Ray> limited;
  for (const Ray& ray : make_rays(s, 1200, seed(416))) {
    Ray r = ray;
    Intersection first;
    if (!linear_closest(prims, r, &first)) {
      Ray m = ray;
      m.max_t = 5.0;
      limited.push_back(m);
      continue;
    }
    const double t = first.t;
    Ray a = ray, b = ray, c = ray, d = ray, e = ray;
    a.max_t = 0.5 * t;
    b.max_t = t;
    c.min_t = t * (1.0 + 1e-7) + 1e-9;
    d.min_t = 0.5 * t;
    e.max_t = 1.5 * t;
    limited.insert(limited.end(), {a, b, c, d, e});
  }
  expect_agrees_with_linear_scan(bvh, prims, limited, s.name + ", limited [min_t, max_t]", true, true);
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
  EXPECT_LE(student.tests(), 1.5 * framework.tests() + 0.5)
      << s.name << ": your closest-hit traversal makes " << student.tests()
      << " primitive tests per ray; an ordered traversal with pruning by max_t on the same tree makes "
      << framework.tests() << ". Visit the child whose box the ray enters first, and skip a box whose entry t lies "
      << "beyond r.max_t.\n  yours:     " << student << "\n  framework: " << framework;
  EXPECT_LE(student.nodes(), 1.5 * framework.nodes() + 1.0)
      << s.name << ": your traversal reaches " << student.nodes() << " nodes per ray, the ordered one "
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

// The same grid with zero components of -0.0 (1 / -0.0 is -inf, so on a slab
// plane the NaN lands in t_near while t_far is -inf, or t_near is +inf): a
// swap decided by `t_near > t_far` misses these boxes.
GRADED_TEST(BVHCorrectness, NegativeZeroComponentsOnGridLines, "P2T3", 0.5, Hidden) {
  Part2Scene s;
  s.name = "axis-aligned unit grid in z = 0, rays with -0.0 components and origins on grid lines";
  s.add_mesh(make_flat_grid(32, 32.0, 0.0, 0.0, 0));
  auto prims = s.primitives();
  CountedBVH bvh(prims, 4);
  expect_agrees_with_linear_scan(bvh, prims, grid_aligned_rays(600, seed(421), -0.0), s.name, true, true);
}

}  // namespace
}  // namespace pt::test::p2
