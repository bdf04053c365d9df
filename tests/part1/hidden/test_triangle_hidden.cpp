// Hidden P1T3 tests: shared edges, rays in the triangle's plane, random rays
// against an independent solver.
#include <algorithm>
#include <sstream>

#include "../triangle_cases.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt::test::p1 {
namespace {

GRADED_TEST(TriangleIntersect, SharedEdgeCannotSlipThrough, "P1T3", 0.5, Hidden) {
  // Two triangles sharing an edge, and rays through points exactly on that
  // edge. All coordinates are small dyadic numbers and each triangle's
  // (unnormalised) normal is axis-aligned with a power-of-two length, so every
  // correct formulation computes the weights on the shared edge as exactly 0
  // (or their sum as exactly 1): a point on an edge must count as inside.
  // Every rotation of both triangles' vertex order is tried, so each of the
  // three edge conditions is exercised.
  struct Config {
    Vec3 a[3], b[3];  // two triangles on either side of the edge e0-e1
    Vec3 e0, e1;
    std::vector<Vec3> dirs;
  };
  const Config configs[] = {
      // The unit square in z = 0 split along its diagonal.
      {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)},
       {Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
       Vec3(0, 0, 0),
       Vec3(1, 1, 0),
       {Vec3(0, 0, -1), Vec3(0.25, -0.5, -1), Vec3(-0.5, 0.25, 1)}},
      // Two triangles in the plane y = 1 sharing the edge (0,1,0)-(1,1,1).
      {{Vec3(0, 1, 0), Vec3(2, 1, 1), Vec3(1, 1, 1)},
       {Vec3(0, 1, 0), Vec3(1, 1, 1), Vec3(0, 1, 2)},
       Vec3(0, 1, 0),
       Vec3(1, 1, 1),
       {Vec3(0, -1, 0), Vec3(0.5, -1, -0.25), Vec3(-0.75, 0.5, 0.125)}},
  };
  for (const Config& cfg : configs)
    for (int ra = 0; ra < 3; ++ra)
      for (int rb = 0; rb < 3; ++rb) {
        TriangleSet set;
        const Triangle& ta = set.add(cfg.a[ra], cfg.a[(ra + 1) % 3], cfg.a[(ra + 2) % 3]);
        const Triangle& tb = set.add(cfg.b[rb], cfg.b[(rb + 1) % 3], cfg.b[(rb + 2) % 3]);
        for (double s : {0.25, 0.5, 0.625})
          for (const Vec3& d : cfg.dirs) {
            Vec3 p = cfg.e0 + s * (cfg.e1 - cfg.e0);
            Ray r(p - 2.0 * d, d);
            std::ostringstream why = stream15();
            why << "The ray hits the point " << p << " of the edge shared by\n  " << describe(ta) << "\n  "
                << describe(tb) << "\nray " << r
                << "\nA point on an edge belongs to the triangle: test b >= 0 and b1 + b2 <= 1, not > and <.";
            EXPECT_TRUE(ta.has_intersection(r) || tb.has_intersection(r))
                << "has_intersection missed both triangles. " << why.str();
            Intersection isect;
            bool hit = ta.intersect(r, &isect);
            hit = tb.intersect(r, &isect) || hit;
            ASSERT_TRUE(hit) << "intersect missed both triangles. " << why.str();
          }
      }
}

GRADED_TEST(TriangleIntersect, RayInItsPlaneMisses, "P1T3", 0.5, Hidden) {
  // A ray lying in the triangle's plane (det = 0 in Moller-Trumbore) sees no
  // area: it misses, without NaN, even when it crosses the triangle.
  TriangleSet set;
  const Triangle& tri = set.add(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
  for (const Ray& r0 : {Ray(Vec3(-1, 0.5, 0), Vec3(1, 0, 0)), Ray(Vec3(0.5, 0.25, 0), Vec3(0, 1, 0)),
                        Ray(Vec3(3, 3, 0), Vec3(-1, -1, 0))}) {
    const std::string ctx = context(tri, r0);
    Ray r = r0;
    EXPECT_FALSE(tri.has_intersection(r)) << "has_intersection hit a ray lying in the triangle's plane.\n" << ctx;
    Intersection isect;
    EXPECT_FALSE(tri.intersect(r, &isect)) << "intersect hit a ray lying in the triangle's plane; t = " << isect.t
                                           << "\n"
                                           << ctx;
    EXPECT_FALSE(std::isnan(r.max_t) || std::isnan(isect.t)) << "NaN after a ray in the plane.\n" << ctx;
  }
}

GRADED_TEST(TriangleIntersect, RandomRaysMatchIndependentSolver, "P1T3", 0.5, Hidden) {
  // The test's own solver: intersect the ray with the triangle's plane, then
  // find the weights of the hit point from sub-triangle areas. Cases within
  // 1e-6 of an edge or of the t range's ends, or nearly parallel to the
  // plane, are skipped (rounding may legitimately go either way there).
  Rng rng(seed(0x7122));
  int checked = 0;
  for (int k = 0; k < 3000; ++k) {
    RandomTriangleCase c = random_triangle_case(rng, k % 2 == 1);
    const Triangle& tri = *c.set->tris[0];
    const Ray& r = c.ray;
    Vec3 e1 = tri.p2() - tri.p1(), e2 = tri.p3() - tri.p1(), n = glm::cross(e1, e2);
    double nn = glm::dot(n, n), denom = glm::dot(n, r.d);
    if (std::abs(denom) < 1e-3 * std::sqrt(nn) * glm::length(r.d) || nn < 1e-6) continue;
    double t = glm::dot(n, tri.p1() - r.o) / denom;
    Vec3 q = r.at(t) - tri.p1();
    double b2 = glm::dot(glm::cross(q, e2), n) / nn, b3 = glm::dot(glm::cross(e1, q), n) / nn, b1 = 1 - b2 - b3;
    double margin = std::min({std::abs(b1), std::abs(b2), std::abs(b3), std::abs(t - r.min_t), std::abs(t - r.max_t)});
    if (margin < 1e-6) continue;
    ++checked;
    bool expected = b1 >= 0 && b2 >= 0 && b3 >= 0 && t >= r.min_t && t <= r.max_t;
    std::ostringstream why = stream15();
    why << "The ray meets the triangle's plane at t = " << t << " with weights " << Vec3(b1, b2, b3)
        << (expected ? ": a hit" : ": a miss") << ".\n"
        << context(tri, r);
    Ray r1 = r, r2 = r;
    Intersection isect;
    ASSERT_EQ(tri.has_intersection(r1), expected) << "has_intersection. " << why.str();
    ASSERT_EQ(tri.intersect(r2, &isect), expected) << "intersect. " << why.str();
    if (expected) {
      ASSERT_TRUE(Near("isect.t", isect.t, t, 1e-7 * std::max(1.0, std::abs(t)))) << "\n" << why.str();
      ASSERT_TRUE(VecNear("isect.barycentric", isect.barycentric, Vec3(b1, b2, b3), 1e-7)) << "\n" << why.str();
    }
  }
  EXPECT_GT(checked, 2000) << "too many random cases were skipped; the test itself is broken";
}

}  // namespace
}  // namespace pt::test::p1
