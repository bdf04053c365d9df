// P2T3 BVHAccel::intersect and BVHAccel::has_intersection: agreement with a
// linear scan over every primitive on thousands of seeded rays, and the work
// of the traversal (ordered, pruned; any-hit stops at
// the first hit), counted as described in tests/support/bvh_checks.h.
// Triangle and Sphere intersection are the reference's here (Part 1).
#include <algorithm>
#include <cmath>
#include <iomanip>

#include "core/rng.h"
#include "common.h"

namespace pt::test::part2 {
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

// --- The ray's interval and deep trees ---------------------------------------------------

// The primitive tests an any-hit query may make on `ray`: those of the leaves
// whose box, and every ancestor's, the ray enters within [min_t, max_t]
// (the framework's closed slab test on the boxes as stored; 1e-9 of slack on
// each end, relative, so that rounding at a touch is not counted against you).
size_t tests_within_range(const FlatTree& tree, const Ray& ray) {
  if (tree.nodes.empty()) return 0;
  const double slack = 1e-9 * std::max(1.0, std::abs(ray.max_t) < kInf ? std::abs(ray.max_t) : 1.0);
  size_t bound = 0;
  std::vector<int> todo{0};
  while (!todo.empty()) {
    const FlatNode& n = tree.nodes[size_t(todo.back())];
    todo.pop_back();
    double t0 = ray.min_t - slack, t1 = ray.max_t + slack;
    if (!slab_closed(n.bb, ray, t0, t1)) continue;
    if (n.leaf()) {
      bound += n.size();
    } else {
      todo.push_back(n.left);
      todo.push_back(n.right);
    }
  }
  return bound;
}

// Shadow rays end at their light: any hit tests no primitive of a leaf that
// the ray does not enter within [min_t, max_t] (handout, section 4), however
// much geometry lies on its line beyond. Sixteen stacked sheets, rays from
// above or below the stack whose range ends before the first sheet (a light
// between the origin and the stack), and triangle-soup shadow rays between
// two random points of the scene. Exact: the bound is the size of the leaves
// the ray enters within its range, on your own tree. Measured: a correct
// traversal stays within it on every ray (seed offsets 0 to 19); one that
// tests boxes on [0, inf) makes 65 primitive tests per sheet ray where the
// leaves entered hold 0.01 (it tests every leaf its line crosses), and
// oversteps the bound on 141 of the 400 soup rays.
GRADED_TEST(BVHTraversal, AnyHitStaysWithinTheRayInterval, "P2T3", 0.5, Visible) {
  Part2Scene layers = make_layers(seed(421), 16);
  Part2Scene soup = make_soup(seed(422), 2000, 50);
  struct Case {
    const Part2Scene* scene;
    std::vector<Ray> rays;
  } cases[] = {{&layers, {}}, {&soup, {}}};
  Rng rng(seed(423), 7);
  {
    auto prims = layers.primitives();
    for (Ray r : make_layer_rays(layers, 400, seed(424))) {
      Ray probe = r;
      Intersection first;
      if (!linear_closest(prims, probe, &first)) continue;
      r.max_t = (0.1 + 0.8 * rng.uniform()) * first.t;  // the light is before the first sheet
      cases[0].rays.push_back(r);
    }
  }
  {
    const BBox b = soup.bounds();
    auto point = [&] { return b.min + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * b.extent(); };
    for (int i = 0; i < 400; ++i) {
      const Vec3 from = point(), to = point();
      Ray r(from, to - from);
      r.min_t = 1e-4;
      r.max_t = 1.0 - 1e-4;  // from a point to a light at `to`
      cases[1].rays.push_back(r);
    }
  }
  for (const Case& c : cases) {
    auto prims = c.scene->primitives();
    CountedBVH bvh(prims, 4);
    if (!expect_valid_tree(bvh, c.scene->name)) return;
    int over = 0, wrong = 0, reported = 0;
    WorkTotals work;
    size_t bound_sum = 0;
    for (const Ray& ray : c.rays) {
      QueryWork w;
      const bool hit = bvh.any(ray, &w);
      work.add(w);
      const size_t bound = tests_within_range(bvh.tree(), ray);
      bound_sum += bound;
      if (hit != linear_any(prims, ray)) {
        ++wrong;
        if (reported++ < kMaxReported)
          ADD_FAILURE() << c.scene->name << ": ray " << ray << "\nhas_intersection returned " << hit
                        << ", a linear scan " << !hit;
      } else if (w.primitive_tests > bound) {
        ++over;
        if (reported++ < kMaxReported)
          ADD_FAILURE() << c.scene->name << ": ray " << ray << "\nhas_intersection made " << w.primitive_tests
                        << " primitive tests; the leaves whose boxes the ray enters within [min_t, max_t] hold "
                        << bound << ". Test each box on the ray's own interval [r.min_t, r.max_t], not on "
                        << "[0, inf): a shadow ray ends at its light.";
      }
    }
    EXPECT_EQ(wrong, 0) << c.scene->name << ": rays on which any hit disagrees with a linear scan";
    EXPECT_EQ(over, 0) << c.scene->name << ": " << over << " of " << c.rays.size()
                       << " rays tested primitives of leaves they do not enter within their interval; yours: " << work
                       << "; the leaves entered hold " << double(bound_sum) / double(c.rays.size())
                       << " primitives per ray";
  }
}

// A chain of slabs: 60 triangles along x, triangle k spanning the x range
// [16^-k, 16^(1-k)], all with the same extent in y and z, a box around the
// x axis. A surface-area builder peels them off one or two per level (the
// reference: depth 36 at leaves of one, 35 at leaves of two), and a ray along
// +x near the axis enters both children at every level, the deeper first: it
// defers a subtree per level. It misses every triangle (each lies beside the
// axis in y and z) but two: the farthest, and the fourth-smallest, the
// closest hit, which waits in a subtree deferred about 33 levels down. A
// traversal whose fixed stack drops a subtree when full (16 entries: every
// ray misses its closest hit) loses it; one that recurses, or grows or sizes
// its stack for the tree, does not. Exact agreement with a linear scan.
GRADED_TEST(BVHCorrectness, DeepTreeManyDeferredSubtrees, "P2T3", 0.5, Visible) {
  Part2Scene s;
  s.name = "60 slabs along x, sizes 16^-k (a tree as deep as the scene), rays along the chain";
  const int n = 60;
  for (int k = 0; k < n; ++k) {
    const double hi = 16.0 * std::pow(1.0 / 16.0, k), lo = hi / 16.0, mid = 0.5 * (lo + hi);
    if (k == 0 || k == n - 4)
      s.add_triangle(Vec3(lo, -0.9, -0.9), Vec3(hi, 1, -0.9), Vec3(mid, -0.9, 1));  // y + z <= 0.1: hit
    else
      s.add_triangle(Vec3(lo, 1, 1), Vec3(hi, 1, -0.9), Vec3(mid, -0.9, 1));  // its y + z >= 0.1: missed
  }
  auto prims = s.primitives();
  std::vector<Ray> rays;
  Rng rng(seed(425), 9);
  for (int i = 0; i < 200; ++i) {
    auto u = [&](double a) { return a * (2.0 * rng.uniform() - 1.0); };
    rays.emplace_back(Vec3(-1.0, u(0.02), u(0.02)), Vec3(1.0, u(0.002), u(0.002)));
  }
  for (size_t leaf : {size_t(1), size_t(2)}) {
    CountedBVH bvh(prims, leaf);
    if (!expect_valid_tree(bvh, s.name)) return;
    testing::Test::RecordProperty("depth_leaf" + std::to_string(leaf), std::to_string(bvh.structure().max_depth));
    expect_agrees_with_linear_scan(bvh, prims, rays, s.name + ", max_leaf_size " + std::to_string(leaf), true, true);
  }
}

}  // namespace
}  // namespace pt::test::part2
