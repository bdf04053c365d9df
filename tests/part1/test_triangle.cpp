// P1T3 Triangle::has_intersection and Triangle::intersect, on the cases of
// triangle_cases.h.
#include <sstream>

#include "hit_record.h"
#include "support/graded.h"
#include "support/seed.h"
#include "triangle_cases.h"

namespace pt::test::part1 {
namespace {

GRADED_TEST(TriangleIntersect, HitDistanceAndPoint, "P1T3", 1, Visible) {
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  for (const HitCase& c : kHits) {
    Ray r = ray_to(tri, c.w1, c.w2, c.w3, c.d, c.t);
    const std::string ctx = context(tri, r, &c);
    ASSERT_TRUE(tri.has_intersection(r)) << "has_intersection missed.\n" << ctx;
    Intersection isect;
    ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed.\n" << ctx;
    ASSERT_TRUE(Near("isect.t", isect.t, c.t, kTol)) << "\n" << ctx;
    Vec3 p = c.w1 * tri.p1() + c.w2 * tri.p2() + c.w3 * tri.p3();
    ASSERT_TRUE(VecNear("the hit point o + t d", r.at(isect.t), p, kTol)) << "\n" << ctx;
  }
}

GRADED_TEST(TriangleIntersect, Barycentrics, "P1T3", 0.5, Visible) {
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  for (const HitCase& c : kHits) {
    Ray r = ray_to(tri, c.w1, c.w2, c.w3, c.d, c.t);
    const std::string ctx = context(tri, r, &c);
    Intersection isect;
    ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed.\n" << ctx;
    ASSERT_TRUE(VecNear("isect.barycentric", isect.barycentric, Vec3(c.w1, c.w2, c.w3), kTol))
        << "\nThe barycentric vector holds the weights of (p1, p2, p3), in that order; they sum to 1.\n"
        << ctx;
  }
}

GRADED_TEST(TriangleIntersect, InterpolatedNormal, "P1T3", 1, Visible) {
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  for (const HitCase& c : kHits) {
    Ray r = ray_to(tri, c.w1, c.w2, c.w3, c.d, c.t);
    const std::string ctx = context(tri, r, &c);
    Intersection isect;
    ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed.\n" << ctx;
    Vec3 expected = glm::normalize(c.w1 * tri.n1() + c.w2 * tri.n2() + c.w3 * tri.n3());
    ASSERT_TRUE(VecNear("isect.n", isect.n, expected, kTol))
        << "|isect.n| = " << glm::length(isect.n)
        << "\nThe normal is the vertex normals weighted by the barycentrics (n1 by the weight of p1, n2 by that of "
           "p2, n3 by that of p3), then normalised.\n"
        << ctx;
  }
}

GRADED_TEST(TriangleIntersect, RecordsPrimitiveAndBsdf, "P1T3", 0.5, Visible) {
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  Ray r = ray_to(tri, 0.2, 0.3, 0.5, Vec3(0.0, 0.0, -1.0), 2.0);
  const std::string ctx = context(tri, r);
  Intersection isect;
  ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed.\n" << ctx;
  EXPECT_EQ(isect.primitive, &tri) << "isect.primitive must be the triangle hit (this).\n" << ctx;
  EXPECT_EQ(isect.bsdf, tri.get_bsdf()) << "isect.bsdf must be the triangle's get_bsdf().\n" << ctx;
}

// Every field of the hit record, written on a hit over what an earlier hit
// on another primitive left there; nothing written on a miss; the ray's
// range changed only by intersect() on a hit.
GRADED_TEST(TriangleIntersect, HitRecordOnHitAndMiss, "P1T3", 0.5, Visible) {
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  TriangleSet others;
  const Triangle& other = others.add(Vec3(5, 5, 5), Vec3(6, 5, 5), Vec3(5, 6, 5));
  const Intersection before = earlier_hit(&other, other.get_bsdf());
  for (const HitCase& c : kHits) {
    const Ray base = ray_to(tri, c.w1, c.w2, c.w3, c.d, c.t);
    const std::string ctx = context(tri, base, &c);
    Ray r = base;
    ASSERT_TRUE(tri.has_intersection(r)) << "has_intersection missed.\n" << ctx;
    ASSERT_TRUE(range_unchanged("has_intersection", r, base)) << "\n" << ctx;
    Intersection isect = before;
    ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed.\n" << ctx;
    const Vec3 n = glm::normalize(c.w1 * tri.n1() + c.w2 * tri.n2() + c.w3 * tri.n3());
    EXPECT_TRUE(Near("isect.t", isect.t, c.t, kTol)) << "\n" << ctx;
    EXPECT_TRUE(VecNear("isect.n", isect.n, n, kTol)) << "\n" << ctx;
    EXPECT_TRUE(VecNear("isect.barycentric", isect.barycentric, Vec3(c.w1, c.w2, c.w3), kTol)) << "\n" << ctx;
    EXPECT_EQ(isect.primitive, &tri) << "isect.primitive after a hit on this triangle\n" << ctx;
    EXPECT_EQ(isect.bsdf, tri.get_bsdf()) << "isect.bsdf after a hit on this triangle\n" << ctx;
    EXPECT_EQ(r.max_t, isect.t) << "r.max_t after the hit\n" << ctx;
    EXPECT_EQ(r.min_t, base.min_t) << "r.min_t after the hit\n" << ctx;
    if (testing::Test::HasFailure()) return;
    // Misses of the same line: the range ends just before the hit, starts just
    // after it; and a ray beside the triangle.
    Ray short_ray = base, late_ray = base;
    short_ray.max_t = 0.99 * c.t;
    late_ray.min_t = 1.01 * c.t;
    const Vec3 beyond = 1.2 * tri.p1() - 0.1 * tri.p2() - 0.1 * tri.p3();
    for (const Ray& miss : {short_ray, late_ray, Ray(beyond - c.t * c.d, c.d)})
      EXPECT_TRUE(miss_changes_nothing(tri, miss, before)) << "\n" << context(tri, miss);
  }
}

GRADED_TEST(TriangleIntersect, MissesBesideEachEdge, "P1T3", 0.5, Visible) {
  // Points of the triangle's plane just outside it: beyond each edge (one
  // weight slightly negative) and beyond each vertex (two negative).
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  const Vec3 outside[] = {{-0.01, 0.5, 0.51}, {0.5, -0.01, 0.51},   {0.5, 0.51, -0.01}, {1.02, -0.01, -0.01},
                          {-0.01, 1.02, -0.01}, {-0.01, -0.01, 1.02}, {-0.5, 0.8, 0.7},   {2.0, -1.5, 0.5}};
  for (const Vec3& w : outside)
    for (const Vec3& d : {glm::normalize(Vec3(-0.2, -0.3, -1.0)), glm::normalize(Vec3(0.3, 0.2, 1.0))}) {
      Ray r = ray_to(tri, w.x, w.y, w.z, d, 2.0);
      std::ostringstream why = stream15();
      why << "The ray crosses the triangle's plane at weights " << w << ", outside the triangle.\n"
          << context(tri, r);
      EXPECT_FALSE(tri.has_intersection(r)) << "has_intersection hit. " << why.str();
      Intersection isect;
      EXPECT_FALSE(tri.intersect(r, &isect)) << "intersect hit. " << why.str();
      ASSERT_EQ(r.max_t, kInf) << "A miss must leave max_t alone. " << why.str();
    }
}

GRADED_TEST(TriangleIntersect, HitsBothFaces, "P1T3", 0.5, Visible) {
  // Triangles are two-sided: a ray hits whichever side it comes from.
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  for (const HitCase& c : kHits)
    for (double side : {1.0, -1.0}) {
      Ray r = ray_to(tri, c.w1, c.w2, c.w3, side * c.d, c.t);
      const std::string ctx = context(tri, r);
      ASSERT_TRUE(tri.has_intersection(r)) << "has_intersection missed (back faces must be hit too).\n" << ctx;
      Intersection isect;
      ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed (back faces must be hit too).\n" << ctx;
      ASSERT_TRUE(Near("isect.t", isect.t, c.t, kTol)) << "\n" << ctx;
    }
}

GRADED_TEST(TriangleIntersect, RespectsTRange, "P1T3", 0.5, Visible) {
  // The ray reaches the triangle at t = 2; it hits only if 2 is in [min_t, max_t].
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  struct Range {
    double min_t, max_t;
    bool hit;
  };
  const Range ranges[] = {{0.0, kInf, true}, {1.5, 2.5, true}, {0.0, 1.5, false}, {2.5, kInf, false}, {3.0, 4.0, false}};
  for (double t_hit : {2.0, -2.0})  // -2: the triangle is behind the ray's origin
    for (const Range& rg : ranges) {
      Ray r = ray_to(tri, 0.3, 0.3, 0.4, glm::normalize(Vec3(0.2, -0.4, -1.0)), t_hit);
      r.min_t = rg.min_t;
      r.max_t = rg.max_t;
      bool expected = rg.hit && t_hit > 0;
      std::ostringstream why = stream15();
      why << "The ray meets the triangle's plane inside the triangle at t = " << t_hit
          << "; it hits only when min_t <= t <= max_t.\n"
          << context(tri, r);
      EXPECT_EQ(tri.has_intersection(r), expected) << "has_intersection. " << why.str();
      Intersection isect;
      EXPECT_EQ(tri.intersect(r, &isect), expected) << "intersect. " << why.str();
    }
}

GRADED_TEST(TriangleIntersect, ShrinksMaxT, "P1T3", 0.5, Visible) {
  auto set = general_triangle();
  const Triangle& tri = *set->tris[0];
  for (const HitCase& c : kHits) {
    Ray r = ray_to(tri, c.w1, c.w2, c.w3, c.d, c.t);
    r.max_t = 100.0;
    const std::string ctx = context(tri, r, &c);
    Intersection isect;
    ASSERT_TRUE(tri.intersect(r, &isect)) << "intersect missed.\n" << ctx;
    ASSERT_TRUE(Near("r.max_t after the hit", r.max_t, c.t, kTol))
        << "\nOn a hit, intersect must set r.max_t = t so that farther hits are rejected.\n"
        << ctx;
  }
}

GRADED_TEST(TriangleIntersect, KeepsNearerHit, "P1T3", 0.5, Visible) {
  // Two parallel triangles on one ray, at t = 2 (near) and t = 3 (far). In
  // either order, the closest-hit query must end with the near one.
  TriangleSet set;
  const Triangle& near = set.add(Vec3(-1, -1, 0), Vec3(2, -1, 0), Vec3(-1, 2, 0));
  const Triangle& far = set.add(Vec3(-1, -1, -1), Vec3(2, -1, -1), Vec3(-1, 2, -1));
  const Ray base(Vec3(0.25, 0.25, 2.0), Vec3(0.0, 0.0, -1.0));
  std::ostringstream tris = stream15();
  tris << "near " << describe(near) << " (t = 2)\nfar " << describe(far) << " (t = 3)\nray " << base;

  Ray r = base;
  Intersection isect;
  ASSERT_TRUE(near.intersect(r, &isect)) << "intersect missed the near triangle.\n" << tris.str();
  EXPECT_FALSE(far.intersect(r, &isect))
      << "After hitting the near triangle, the far one (t = 3 > r.max_t) must be rejected.\n"
      << tris.str();
  EXPECT_EQ(isect.primitive, &near) << "A farther triangle replaced the nearer hit.\n" << tris.str();
  EXPECT_TRUE(Near("isect.t", isect.t, 2.0, kTol)) << "\n" << tris.str();

  r = base;
  isect = Intersection();
  ASSERT_TRUE(far.intersect(r, &isect)) << "intersect missed the far triangle.\n" << tris.str();
  ASSERT_TRUE(near.intersect(r, &isect)) << "intersect missed the near triangle after the far one.\n" << tris.str();
  EXPECT_EQ(isect.primitive, &near) << "The nearer hit must replace the farther one.\n" << tris.str();
  EXPECT_TRUE(Near("isect.t", isect.t, 2.0, kTol)) << "\n" << tris.str();
  EXPECT_TRUE(Near("r.max_t", r.max_t, 2.0, kTol)) << "\n" << tris.str();
}

GRADED_TEST(TriangleIntersect, DegenerateNeverHits, "P1T3", 0.5, Visible) {
  // Zero-area triangles (collinear or repeated vertices) have no interior:
  // no ray hits them, even one aimed right at their points, and nothing they
  // report may be NaN. Small integer coordinates keep every product exact.
  TriangleSet set;
  set.add(Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 2, 0));  // collinear
  set.add(Vec3(0, 0, 0), Vec3(2, 2, 0), Vec3(1, 1, 0));  // collinear, middle vertex last
  set.add(Vec3(1, 1, 0), Vec3(1, 1, 0), Vec3(2, 0, 0));  // two equal vertices
  set.add(Vec3(1, 1, 0), Vec3(1, 1, 0), Vec3(1, 1, 0));  // a single point
  const Ray rays[] = {
      Ray(Vec3(1, 1, 2), Vec3(0, 0, -1)),          // straight down onto (1, 1, 0)
      Ray(Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1)),  // from below onto (1, 1, 0)
      Ray(Vec3(-1, -1, 0), Vec3(1, 1, 0)),          // along the line of the collinear ones
      Ray(Vec3(1, 1, 0), Vec3(0, 0, 1)),            // starting on (1, 1, 0)
      Ray(Vec3(1.5, 0.5, 1), Vec3(0, 0, -1)),       // onto the segment (1,1)-(2,0)
  };
  for (const auto& t : set.tris)
    for (const Ray& r0 : rays) {
      Ray r = r0;
      std::ostringstream why = stream15();
      why << "zero-area " << describe(*t) << "\nray " << r0;
      EXPECT_FALSE(t->has_intersection(r)) << "has_intersection hit a " << why.str();
      Intersection isect;
      bool hit = t->intersect(r, &isect);
      EXPECT_FALSE(hit) << "intersect hit a " << why.str() << "\nreported t = " << isect.t << ", n = " << isect.n;
      EXPECT_FALSE(std::isnan(r.max_t)) << "r.max_t became NaN on a " << why.str();
      EXPECT_FALSE(std::isnan(isect.t) || std::isnan(isect.n.x) || std::isnan(isect.barycentric.x))
          << "the intersection record holds NaN after a " << why.str();
    }
}

GRADED_TEST(TriangleIntersect, HasIntersectionAgreesWithIntersect, "P1T3", 0.5, Visible) {
  Rng rng(seed(0x7121));
  for (int k = 0; k < 2000; ++k) {
    RandomTriangleCase c = random_triangle_case(rng, k % 2 == 1);
    const Triangle& tri = *c.set->tris[0];
    Ray r1 = c.ray, r2 = c.ray;
    Intersection isect;
    bool any = tri.has_intersection(r1);
    bool closest = tri.intersect(r2, &isect);
    ASSERT_EQ(any, closest) << "has_intersection and intersect disagree (random ray " << k << ").\n"
                            << context(tri, c.ray);
  }
}

}  // namespace
}  // namespace pt::test::part1
