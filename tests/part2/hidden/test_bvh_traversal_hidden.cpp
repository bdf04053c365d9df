// Hidden P2T3 tests: limited ray intervals, and -0.0 direction components
// along grid lines.
#include "../part2_common.h"

namespace pt::test::p2 {
namespace {

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
