// The reference triangle test is watertight: a ray aimed at the edge two
// triangles share hits at least one of them, whatever rounding does. The
// experiment behind the reference's choice (handouts/part1.md, section 3):
// on these 68,583 rays Moller-Trumbore (inclusive comparisons, double
// precision) lets 5,198 through (7.6%), the watertight test of Woop, Benthin
// and Wald none.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "support/part1_builders.h"

namespace pt {
namespace {

using test::part1::describe;
using test::part1::TriangleSet;

// Side of p from the plane through o, a, b.
double side(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& p) {
  return glm::dot(glm::cross(a - o, b - o), p - o);
}

TEST(ReferenceTriangle, IsWatertightOnSharedEdges) {
  // 1000 quads (p0, p1, p2, p3) split along the diagonal p0-p2, half of them
  // planar, half with four random corners; 100 rays each from random origins,
  // aimed at random points of the diagonal (away from its ends) with
  // directions of random length. A ray counts only when, seen from its
  // origin, p1 and p3 lie on opposite sides of the diagonal (otherwise the
  // two triangles overlap there and the diagonal is an outer edge).
  Rng rng(0x3a7e);
  auto u = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  auto v = [&](double lo, double hi) { return Vec3(u(lo, hi), u(lo, hi), u(lo, hi)); };
  int rays = 0, misses = 0;
  for (int q = 0; q < 1000; ++q) {
    Vec3 p[4];
    if (q % 2 == 0) {
      const Vec3 c = v(-3, 3), e1 = v(-1, 1), e2 = v(-1, 1);
      const double angles[4] = {u(0.0, 1.5), u(1.6, 3.1), u(3.2, 4.6), u(4.7, 6.2)};
      for (int k = 0; k < 4; ++k) p[k] = c + u(0.3, 1.0) * (std::cos(angles[k]) * e1 + std::sin(angles[k]) * e2);
    } else {
      for (Vec3& corner : p) corner = v(-3, 3);
    }
    TriangleSet set;
    const Triangle& a = set.add(p[0], p[1], p[2]);
    const Triangle& b = set.add(p[0], p[2], p[3]);
    for (int k = 0; k < 100; ++k) {
      const Vec3 o = v(-8, 8);
      if (side(o, p[0], p[2], p[1]) * side(o, p[0], p[2], p[3]) >= 0.0) continue;
      const Vec3 target = p[0] + u(0.02, 0.98) * (p[2] - p[0]);
      const Ray r(o, (target - o) * u(0.1, 10.0));
      ++rays;
      Ray ra = r, rb = r;
      Intersection isect;
      const bool hit = a.has_intersection(r) || b.has_intersection(r) || a.intersect(ra, &isect) ||
                       b.intersect(rb, &isect);
      if (!hit && misses++ < 5)
        ADD_FAILURE() << "the ray " << r << " aimed at the shared edge misses both " << describe(a) << " and "
                      << describe(b);
    }
  }
  RecordProperty("rays", rays);
  RecordProperty("misses", misses);
  EXPECT_GT(rays, 30000) << "too few rays counted; the test itself is broken";
  EXPECT_EQ(misses, 0) << "of " << rays << " rays aimed at a shared edge slipped between its two triangles";
}

}  // namespace
}  // namespace pt
