// Hidden P1T4 tests: spheres far smaller and larger than 1, random rays
// against the closed form.
#include <algorithm>
#include <sstream>

#include "../sphere_cases.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt::test::p1 {
namespace {

GRADED_TEST(SphereIntersect, TinyAndHugeSpheres, "P1T4", 0.5, Hidden) {
  // Scale: a sphere of radius 1e-3 seen from 1e3 away, and one of radius 1e4
  // (seen from outside and from inside). A correct double-precision solution
  // is accurate to about eps * D^2 / sqrt(r^2 - h^2): 5e-7 for the tiny sphere
  // at h = 0.9 r, i.e. 5e-4 of its radius. The tolerance is 1% of the radius
  // (the hit point is within r/100 of the exact one); float arithmetic or an
  // absolute epsilon on the discriminant fails it.
  struct Case {
    Vec3 centre;
    double r, D;
    std::vector<double> hs;  // offsets, in radii
    bool inside;
  };
  const Case cases[] = {
      {glm::normalize(Vec3(1, 2, -3)) * 1e3, 1e-3, 1e3, {0.0, 0.5, 0.9}, false},
      {glm::normalize(Vec3(-2, 1, 1)) * 3e4, 1e4, 3e4, {0.0, 0.5, 0.99}, false},
      {Vec3(2e4, -1e4, 5e3), 1e4, 3e3, {0.0, 0.3}, true},  // origin inside, about 3e3 from the centre
  };
  for (const Case& c : cases) {
    Sphere s(c.centre, c.r, &g_bsdf);
    for (double h : c.hs) {
      Approach a = approach(Vec3(0.3, -0.2, 1.0), c.D, h * c.r);
      Ray r = ray_past(s, a);
      const std::string ctx = context(s, r);
      double expected = c.inside ? far_root(s, a) : near_root(s, a);
      Intersection isect;
      ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed.\n" << ctx;
      ASSERT_TRUE(Near("isect.t", isect.t, expected, 1e-2 * c.r)) << "\nThe tolerance is 1% of the radius.\n" << ctx;
      // Passing 1.5 radii from the centre misses.
      Approach miss = a;
      miss.h = 1.5 * c.r;
      Ray rm = ray_past(s, miss);
      if (!c.inside) {
        EXPECT_FALSE(s.has_intersection(rm)) << "has_intersection hit a ray passing 1.5 r from the centre.\n"
                                             << context(s, rm);
      }
    }
  }
}

GRADED_TEST(SphereIntersect, RandomRaysMatchClosedForm, "P1T4", 1, Hidden) {
  // Roots from the closest approach (support/part1_builders.h); cases within
  // 1e-4 r of tangency or 1e-6 of the t range's ends are skipped.
  Rng rng(seed(0x5e3));
  int checked = 0;
  for (int k = 0; k < 3000; ++k) {
    RandomSphereCase c = random_sphere_case(rng, k % 2 == 1);
    const Sphere& s = c.sphere;
    const Ray& r = c.ray;
    Roots roots = closest_approach_roots(r.o, r.d, s.o, s.r);
    bool near_boundary = std::abs(roots.h - s.r) < 1e-4 * s.r;
    for (double t : {roots.t1, roots.t2})
      near_boundary = near_boundary || (roots.real && std::min(std::abs(t - r.min_t), std::abs(t - r.max_t)) < 1e-6);
    if (near_boundary) continue;
    ++checked;
    double t_hit = -1;
    if (roots.real) {
      if (roots.t1 >= r.min_t && roots.t1 <= r.max_t) t_hit = roots.t1;
      else if (roots.t2 >= r.min_t && roots.t2 <= r.max_t) t_hit = roots.t2;
    }
    bool expected = t_hit >= 0;
    std::ostringstream why = stream15();
    if (roots.real) why << "Roots " << roots.t1 << " and " << roots.t2;
    else why << "No real roots (the line passes " << roots.h << " from the centre)";
    why << (expected ? ": a hit.\n" : ": a miss.\n") << context(s, r);
    double t1 = 0, t2 = 0;
    ASSERT_EQ(s.test(r, t1, t2), roots.real) << "test(). " << why.str();
    if (roots.real) {
      ASSERT_TRUE(Near("t1", t1, roots.t1, 1e-7 * std::max(1.0, std::abs(roots.t1)))) << "\n" << why.str();
      ASSERT_TRUE(Near("t2", t2, roots.t2, 1e-7 * std::max(1.0, std::abs(roots.t2)))) << "\n" << why.str();
    }
    Ray r1 = r, r2 = r;
    ASSERT_EQ(s.has_intersection(r1), expected) << "has_intersection. " << why.str();
    Intersection isect;
    ASSERT_EQ(s.intersect(r2, &isect), expected) << "intersect. " << why.str();
    if (expected) {
      ASSERT_TRUE(Near("isect.t", isect.t, t_hit, 1e-7 * std::max(1.0, t_hit))) << "\n" << why.str();
      ASSERT_TRUE(VecNear("isect.n", isect.n, (r.at(t_hit) - s.o) / s.r, 1e-6)) << "\n" << why.str();
    }
  }
  EXPECT_GT(checked, 2500) << "too many random cases were skipped; the test itself is broken";
}

}  // namespace
}  // namespace pt::test::p1
