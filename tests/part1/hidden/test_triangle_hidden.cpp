// Hidden P1T3 tests: shared edges, rays in the triangle's plane, random rays
// against an independent solver.
#include <algorithm>
#include <sstream>

#include "../triangle_cases.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt::test::part1 {
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

GRADED_TEST(TriangleIntersect, HitsExactlyAtTheEndsOfTheRange, "P1T3", 0.5, Hidden) {
  // The interval is closed: a hit at exactly min_t or max_t counts. (1) Rays
  // along an axis, with lengths that are powers of two, onto triangles whose
  // coordinates are small dyadic numbers: every formulation (Moller-Trumbore,
  // a watertight test, plane then barycentrics, a normalised direction)
  // computes the hit distance t* exactly, so [t*, inf), [0, t*] and [t*, t*]
  // must all hit. (2) After intersect has set r.max_t = t, the same ray still
  // hits the same triangle: intersect computes the same t again, bit for bit,
  // and has_intersection does too on these exact cases. A strict min_t < t or
  // t < max_t fails both; no correct solution can (boundary: exactly t*).
  struct Exact {
    Vec3 a, b, c, o, d;
    double t;  // exact hit distance, in units of d
  };
  const Exact cases[] = {
      {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 3}, {0, 0, -1}, 3},
      {{0, 0, 0}, {0, 4, 0}, {4, 0, 0}, {1, 1, 3}, {0, 0, -0.5}, 6},     // the other winding, a short d
      {{2, -1, -1}, {2, 3, -1}, {2, -1, 3}, {-2, 0.5, 0.25}, {2, 0, 0}, 2},  // along +x
      {{1, 5, 0}, {-3, 5, 2}, {1, 5, 4}, {0, -3, 1.5}, {0, 0.25, 0}, 32},  // along +y, a long way
      {{0, 0, -2}, {2, 0, -2}, {0, 2, -2}, {0.5, 0.5, 6}, {0, 0, -4}, 2},
  };
  for (const Exact& c : cases) {
    TriangleSet set;
    const Triangle& tri = set.add(c.a, c.b, c.c);
    struct Range {
      double min_t, max_t;
    };
    for (const Range& rg : {Range{c.t, kInf}, Range{0.0, c.t}, Range{c.t, c.t}}) {
      Ray r(c.o, c.d);
      r.min_t = rg.min_t;
      r.max_t = rg.max_t;
      std::ostringstream why = stream15();
      why << "The ray hits the triangle at exactly t = " << c.t << ", an end of its interval [" << r.min_t << ", "
          << r.max_t << "]: the interval is closed, min_t <= t <= max_t.\n"
          << context(tri, r);
      EXPECT_TRUE(tri.has_intersection(r)) << "has_intersection missed. " << why.str();
      Intersection isect;
      ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed. " << why.str();
      EXPECT_TRUE(Near("isect.t", isect.t, c.t, kTol)) << "\n" << why.str();
    }
    Ray r(c.o, c.d);
    Intersection isect;
    ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed.\n" << context(tri, Ray(c.o, c.d));
    const double t = r.max_t;
    std::ostringstream again = stream15();
    again << "intersect hit at t = " << isect.t << " and set max_t = " << t
          << "; the same ray, tested again, must still hit there (t <= max_t, not t < max_t).\n"
          << context(tri, r);
    EXPECT_TRUE(tri.has_intersection(r)) << "has_intersection missed. " << again.str();
    EXPECT_TRUE(tri.intersect(r, &isect)) << "intersect missed. " << again.str();
  }
  // (2) on the general triangle, for intersect (the same computation twice).
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  for (const HitCase& c : kHits) {
    Ray r = ray_to(tri, c.w1, c.w2, c.w3, c.d, c.t);
    Intersection isect;
    ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed.\n" << context(tri, ray_to(tri, c.w1, c.w2, c.w3, c.d, c.t), &c);
    EXPECT_TRUE(tri.intersect(r, &isect))
        << "intersect hit at t = " << isect.t << " and set max_t = " << r.max_t
        << "; tested again with that max_t it missed (t <= max_t must hold for the same t).\n"
        << context(tri, r, &c);
  }
}

GRADED_TEST(TriangleIntersect, TinyHugeAndSliverTriangles, "P1T3", 0.5, Hidden) {
  // Scale: triangles 1e-6 to 1e-3 across (near the origin and 1000 away),
  // 1e5 across seen from 1e6 away, and slivers 1 long and 1e-7 wide. Every
  // check is relative to the triangle: hits at interior weights (each at
  // least 0.2) must be found with t to 1e-6 relative and the weights to
  // 1e-5; points 1% of the triangle outside an edge must miss. Measured
  // worst errors (t relative / weights): Moller-Trumbore 2.2e-9 / 1e-8 (the
  // tilted sliver: its plane is only known to eps / width), the watertight
  // test 2.5e-11 / 7.4e-9; the tolerances are 450 and 1000 times those.
  // Boundary: a determinant test that depends on the triangle's size, such
  // as the absolute |det| < 1e-6 of the original Moller-Trumbore paper,
  // rejects every triangle whose determinant (proportional to its area times
  // |d|) is below it: all the tiny ones and the slivers here.
  struct Case {
    const char* name;
    Vec3 a, b, c;
    double distance;  // of the ray's origin from the hit point
  };
  const Vec3 far = glm::normalize(Vec3(1, 2, -3)) * 1e3;
  const Case cases[] = {
      {"1e-6 across, at the origin", {0, 0, 0}, {1e-6, 0.2e-6, 0}, {0.3e-6, 0.9e-6, 0.1e-6}, 1.0},
      {"1e-4 across", {0.1, 0.2, 0.3}, Vec3(0.1, 0.2, 0.3) + Vec3(1e-4, 0, 0), Vec3(0.1, 0.2, 0.3) + Vec3(0, 1e-4, 2e-5),
       0.5},
      {"1e-3 across, 1000 from the origin", far, far + Vec3(1e-3, 0.3e-3, 0), far + Vec3(-0.2e-3, 0.8e-3, 0.5e-3), 2.0},
      {"1e5 across, seen from 1e6", {-5e4, -5e4, 0}, {5e4, -4e4, 1e4}, {0, 6e4, -1e4}, 1e6},
      {"a sliver 1 long, 1e-7 wide", {0, 0, 0}, {1, 0, 0}, {1, 1e-7, 0}, 3.0},
      {"a sliver 1 long, 1e-7 wide, tilted", {0.5, 0.5, 0.5}, {1.5, 1.0, 0.0}, {1.5, 1.0, 1e-7}, 3.0},
  };
  const Vec3 dirs[] = {glm::normalize(Vec3(0.2, -0.3, -1.0)), glm::normalize(Vec3(-0.7, 0.4, 0.6)),
                       Vec3(0.5, 1.0, -2.0)};  // |d| != 1
  const Vec3 inside[] = {{0.2, 0.4, 0.4}, {0.6, 0.2, 0.2}, {1.0 / 3, 1.0 / 3, 1.0 / 3}};
  const Vec3 outside[] = {{-0.01, 0.5, 0.51}, {0.5, -0.01, 0.51}, {0.5, 0.51, -0.01}};
  for (const Case& k : cases) {
    TriangleSet set;
    const Triangle& tri = set.add(k.a, k.b, k.c);
    for (const Vec3& d : dirs) {
      const double t = k.distance / glm::length(d);
      for (const Vec3& w : inside) {
        Ray r = ray_to(tri, w.x, w.y, w.z, d, t);
        std::ostringstream why = stream15();
        why << k.name << ": the ray reaches weights " << w << " at t = " << t << ".\n" << context(tri, r);
        EXPECT_TRUE(tri.has_intersection(r)) << "has_intersection missed. " << why.str();
        Intersection isect;
        ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed. " << why.str();
        EXPECT_TRUE(Near("isect.t", isect.t, t, 1e-6 * t)) << "\n" << why.str();
        EXPECT_TRUE(VecNear("isect.barycentric", isect.barycentric, w, 1e-5)) << "\n" << why.str();
      }
      for (const Vec3& w : outside) {
        Ray r = ray_to(tri, w.x, w.y, w.z, d, t);
        std::ostringstream why = stream15();
        why << k.name << ": the ray crosses the triangle's plane at weights " << w
            << ", 1% of the triangle outside an edge.\n"
            << context(tri, r);
        EXPECT_FALSE(tri.has_intersection(r)) << "has_intersection hit. " << why.str();
        Intersection isect;
        EXPECT_FALSE(tri.intersect(r, &isect)) << "intersect hit. " << why.str();
      }
    }
  }
}

}  // namespace
}  // namespace pt::test::part1
