// P1T4 Sphere::test, Sphere::has_intersection, Sphere::intersect, on the
// rays of sphere_cases.h (placed by their closest approach to the centre).
#include <sstream>

#include "hit_record.h"
#include "sphere_cases.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt::test::part1 {
namespace {

GRADED_TEST(SphereTest, RootsInOrder, "P1T4", 1, Visible) {
  // Sphere ahead, sphere behind (both roots negative), origin inside (t1 < 0 < t2).
  const Sphere spheres[] = {Sphere(Vec3(0, 0, -5), 1.0, &g_bsdf), Sphere(Vec3(1, 2, 3), 2.0, &g_bsdf),
                            Sphere(Vec3(-4, 0.5, 1), 0.25, &g_bsdf)};
  const Approach approaches[] = {approach(Vec3(0, 0, -1), 5.0, 0.0),          approach(Vec3(1, 2, -3), 4.0, 0.1),
                                 approach(Vec3(-1, 0.5, 0.2), 10.0, 0.8, 2.0), approach(Vec3(0.3, -1, 0.1), -6.0, 0.5),
                                 approach(Vec3(2, 1, 1), 0.1, 0.2, 4.0),       approach(Vec3(0, 1, 0), 0.0, 0.0)};
  for (const Sphere& s : spheres)
    for (Approach a : approaches) {
      a.h *= s.r;  // keep every ray inside the sphere's radius
      Ray r = ray_past(s, a);
      const std::string ctx = context(s, r);
      double t1 = -1e300, t2 = -1e300;
      ASSERT_TRUE(s.test(r, t1, t2)) << "test() found no real roots; the ray passes " << a.h << " from the centre.\n"
                                     << ctx;
      ASSERT_LE(t1, t2) << "test() must return the roots in order, t1 <= t2.\n" << ctx;
      EXPECT_TRUE(Near("t1", t1, near_root(s, a), kTol))
          << "\nt1 is the smaller root, whatever the ray's t range (it may be negative).\n"
          << ctx;
      EXPECT_TRUE(Near("t2", t2, far_root(s, a), kTol)) << "\nt2 is the larger root.\n" << ctx;
    }
}

GRADED_TEST(SphereTest, NoRealRootsReturnsFalse, "P1T4", 0.5, Visible) {
  Sphere s(Vec3(1, -1, -3), 1.5, &g_bsdf);
  for (double h : {1.0001, 1.1, 2.0, 10.0})
    for (double D : {4.0, -4.0, 0.0}) {
      Approach a = approach(Vec3(0.2, 0.1, -1), D, h * s.r);
      Ray r = ray_past(s, a);
      const std::string ctx = context(s, r);
      double t1, t2;
      EXPECT_FALSE(s.test(r, t1, t2)) << "test() found roots, but the ray passes " << a.h
                                     << " from the centre, outside the radius.\n"
                                     << ctx;
      EXPECT_FALSE(s.has_intersection(r)) << "has_intersection hit.\n" << ctx;
      Intersection isect;
      EXPECT_FALSE(s.intersect(r, &isect)) << "intersect hit.\n" << ctx;
      ASSERT_EQ(r.max_t, kInf) << "A miss must leave max_t alone.\n" << ctx;
    }
}

GRADED_TEST(SphereTest, NonUnitDirection, "P1T4", 0.5, Visible) {
  // t is measured in units of d: with d = k u the roots are (D -+ sqrt(r^2 - h^2)) / k.
  Sphere s(Vec3(0.5, 1, -2), 0.75, &g_bsdf);
  Approach a = approach(Vec3(1, -1, -2), 3.0, 0.3);
  for (double k : {0.25, 3.0}) {
    Ray r = ray_past(s, a);
    r.d *= k;
    const std::string ctx = context(s, r);
    double t1 = 0, t2 = 0;
    ASSERT_TRUE(s.test(r, t1, t2)) << "test() found no roots (|d| = " << k << ").\n" << ctx;
    EXPECT_TRUE(Near("t1", t1, near_root(s, a) / k, kTol))
        << "\n|d| = " << k << ": do not assume a unit direction (a = d.d).\n"
        << ctx;
    EXPECT_TRUE(Near("t2", t2, far_root(s, a) / k, kTol))
        << "\n|d| = " << k << ": do not assume a unit direction (a = d.d).\n"
        << ctx;
  }
}

GRADED_TEST(SphereIntersect, NearRootFromOutside, "P1T4", 0.5, Visible) {
  Sphere s(Vec3(1, 2, 3), 2.0, &g_bsdf);
  for (const Approach& a : {approach(Vec3(0, 0, -1), 5.0, 0.0), approach(Vec3(1, 2, -3), 4.0, 1.9),
                            approach(Vec3(-1, 0.5, 0.2), 10.0, 1.2, 2.0)}) {
    Ray r = ray_past(s, a);
    const std::string ctx = context(s, r);
    ASSERT_TRUE(s.has_intersection(r)) << "has_intersection missed.\n" << ctx;
    Intersection isect;
    ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed.\n" << ctx;
    EXPECT_TRUE(Near("isect.t", isect.t, near_root(s, a), kTol))
        << "\nFrom outside, the hit is the nearer root (the far one is " << far_root(s, a) << ").\n"
        << ctx;
  }
}

GRADED_TEST(SphereIntersect, TangentRayTouches, "P1T4", 0.5, Visible) {
  // The ray grazes the sphere: a double root (discriminant exactly 0 with
  // these numbers, in any formulation). It counts as a hit.
  Sphere s(Vec3(2, 3, -4), 0.5, &g_bsdf);
  Ray r(Vec3(-1, 3.5, -4), Vec3(1, 0, 0));
  const std::string ctx = context(s, r);
  double t1 = 0, t2 = 0;
  ASSERT_TRUE(s.test(r, t1, t2)) << "test(): a tangent ray has one (double) real root; a zero discriminant is a "
                                    "root.\n"
                                 << ctx;
  EXPECT_TRUE(Near("t1", t1, 3.0, kTol) && Near("t2", t2, 3.0, kTol))
      << "t1 = " << t1 << ", t2 = " << t2 << ", expected 3 and 3\n"
      << ctx;
  Intersection isect;
  ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed the tangent ray.\n" << ctx;
  EXPECT_TRUE(Near("isect.t", isect.t, 3.0, kTol)) << "\n" << ctx;
  EXPECT_TRUE(VecNear("isect.n", isect.n, Vec3(0, 1, 0), 1e-6)) << "\n" << ctx;
}

GRADED_TEST(SphereIntersect, OriginInsideHitsFarRoot, "P1T4", 0.5, Visible) {
  // From inside, the near root is behind the origin (t1 < 0 <= min_t): the
  // hit is the far root, and the normal still points outwards.
  Sphere s(Vec3(-1, 0.5, 2), 1.5, &g_bsdf);
  for (const Approach& a : {approach(Vec3(0, 0, -1), 0.0, 0.0), approach(Vec3(1, 2, -3), 0.5, 0.4),
                            approach(Vec3(-1, 0.5, 0.2), -1.0, 0.2, 2.0)}) {
    Ray r = ray_past(s, a);
    const std::string ctx = context(s, r);
    ASSERT_TRUE(s.has_intersection(r)) << "has_intersection missed from inside.\n" << ctx;
    Intersection isect;
    ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed from inside.\n" << ctx;
    EXPECT_TRUE(Near("isect.t", isect.t, far_root(s, a), kTol)) << "\nFrom inside, the hit is the far root.\n" << ctx;
    EXPECT_TRUE(VecNear("isect.n", isect.n, (r.at(far_root(s, a)) - s.o) / s.r, 1e-9))
        << "\nThe normal points outwards, even when the sphere is hit from inside.\n"
        << ctx;
  }
}

GRADED_TEST(SphereIntersect, SphereBehindMisses, "P1T4", 0.5, Visible) {
  Sphere s(Vec3(0, 0, 5), 1.0, &g_bsdf);
  for (const Approach& a : {approach(Vec3(0, 0, -1), -5.0, 0.0), approach(Vec3(0.1, 0.2, -1), -3.0, 0.5)}) {
    Ray r = ray_past(s, a);
    const std::string ctx = context(s, r);
    EXPECT_FALSE(s.has_intersection(r)) << "has_intersection hit a sphere behind the ray (both roots < 0).\n" << ctx;
    Intersection isect;
    EXPECT_FALSE(s.intersect(r, &isect)) << "intersect hit a sphere behind the ray (both roots < 0).\n" << ctx;
    EXPECT_EQ(r.max_t, kInf) << "A miss must leave max_t alone.\n" << ctx;
  }
}

GRADED_TEST(SphereIntersect, RespectsTRange, "P1T4", 0.5, Visible) {
  // Roots 4 and 6; the hit is the nearest root inside [min_t, max_t].
  Sphere s(Vec3(0, 0, -5), 1.0, &g_bsdf);
  struct Range {
    double min_t, max_t, t;  // t < 0: no hit
  };
  const Range ranges[] = {{0, kInf, 4},   {0, 5, 4},      {4.5, kInf, 6}, {4.5, 6.5, 6},
                          {0, 3.9, -1}, {4.5, 5.5, -1}, {6.5, kInf, -1}};
  for (const Range& rg : ranges) {
    Ray r(Vec3(0.0), Vec3(0, 0, -1));
    r.min_t = rg.min_t;
    r.max_t = rg.max_t;
    std::ostringstream why = stream15();
    why << "Roots 4 and 6, t range [" << rg.min_t << ", " << rg.max_t << "]: ";
    if (rg.t < 0) why << "no root in range, a miss.\n";
    else why << "a hit at t = " << rg.t << ".\n";
    why << context(s, r);
    EXPECT_EQ(s.has_intersection(r), rg.t > 0) << "has_intersection. " << why.str();
    Intersection isect;
    bool hit = s.intersect(r, &isect);
    EXPECT_EQ(hit, rg.t > 0) << "intersect. " << why.str();
    if (hit && rg.t > 0) {
      EXPECT_TRUE(Near("isect.t", isect.t, rg.t, kTol)) << "\n" << why.str();
    }
  }
}

GRADED_TEST(SphereIntersect, KeepsNearerHit, "P1T4", 0.5, Visible) {
  // Two spheres on one ray, hit at t = 2 (near) and t = 9 (far).
  Sphere near(Vec3(0, 0, -3), 1.0, &g_bsdf), far(Vec3(0, 0, -10), 1.0, &g_bsdf);
  const Ray base(Vec3(0.0), Vec3(0, 0, -1));
  std::ostringstream both = stream15();
  both << "near " << describe(near) << " (t = 2)\nfar " << describe(far) << " (t = 9)\nray " << base;

  Ray r = base;
  Intersection isect;
  ASSERT_TRUE(near.intersect(r, &isect)) << "intersect missed the near sphere.\n" << both.str();
  EXPECT_TRUE(Near("r.max_t after the hit", r.max_t, 2.0, kTol))
      << "\nOn a hit, intersect must set ray.max_t = t so that farther hits are rejected.\n"
      << both.str();
  EXPECT_FALSE(far.intersect(r, &isect)) << "After the near hit, the far sphere (t = 9 > r.max_t) must be rejected.\n"
                                         << both.str();
  EXPECT_EQ(isect.primitive, &near) << "A farther sphere replaced the nearer hit.\n" << both.str();

  r = base;
  isect = Intersection();
  ASSERT_TRUE(far.intersect(r, &isect)) << "intersect missed the far sphere.\n" << both.str();
  ASSERT_TRUE(near.intersect(r, &isect)) << "intersect missed the near sphere after the far one.\n" << both.str();
  EXPECT_EQ(isect.primitive, &near) << "The nearer hit must replace the farther one.\n" << both.str();
  EXPECT_TRUE(Near("isect.t", isect.t, 2.0, kTol)) << "\n" << both.str();
}

GRADED_TEST(SphereIntersect, OutwardUnitNormal, "P1T4", 0.5, Visible) {
  Sphere s(Vec3(1, -2, 3), 2.5, &g_bsdf);
  Rng rng(seed(0x5e1));
  for (int k = 0; k < 50; ++k) {
    Vec3 dir(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    Approach a = approach(dir, 4.0 + 4.0 * rng.uniform(), 0.99 * s.r * rng.uniform(), 6.3 * rng.uniform());
    Ray r = ray_past(s, a);
    const std::string ctx = context(s, r);
    Intersection isect;
    ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed.\n" << ctx;
    Vec3 expected = (r.at(near_root(s, a)) - s.o) / s.r;
    ASSERT_TRUE(VecNear("isect.n", isect.n, expected, 1e-9))
        << "|isect.n| = " << glm::length(isect.n)
        << "\nThe normal is the unit vector (hit point - centre) / radius, pointing out of the sphere.\n"
        << ctx;
  }
}

GRADED_TEST(SphereIntersect, RecordsPrimitiveAndBsdf, "P1T4", 0.5, Visible) {
  Sphere s(Vec3(0, 0, -4), 1.0, &g_bsdf);
  Ray r(Vec3(0.0), Vec3(0, 0, -1));
  const std::string ctx = context(s, r);
  Intersection isect;
  ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed.\n" << ctx;
  EXPECT_EQ(isect.primitive, &s) << "isect.primitive must be the sphere hit (this).\n" << ctx;
  EXPECT_EQ(isect.bsdf, s.get_bsdf()) << "isect.bsdf must be the sphere's get_bsdf().\n" << ctx;
}

// Every field of the hit record, written on a hit over what an earlier hit on
// a triangle left there (barycentric weights included: a sphere's are 0);
// nothing written on a miss; the ray's range changed only by intersect() on
// a hit. From outside (near root) and from inside (far root).
GRADED_TEST(SphereIntersect, HitRecordOnHitAndMiss, "P1T4", 0.5, Visible) {
  Sphere s(Vec3(1, -2, 3), 2.5, &g_bsdf);
  TriangleSet others;
  const Triangle& other = others.add(Vec3(9, 9, 9), Vec3(10, 9, 9), Vec3(9, 10, 9));
  const Intersection before = earlier_hit(&other, other.get_bsdf());
  const Approach cases[] = {approach(Vec3(0.3, -0.4, 1.0), 6.0, 1.5, 0.4),   // from outside
                            approach(Vec3(-1.0, 0.2, 0.1), 0.5, 0.7, 2.0)};  // from inside
  for (const Approach& a : cases) {
    const Ray base = ray_past(s, a);
    const double t = near_root(s, a) >= 0.0 ? near_root(s, a) : far_root(s, a);
    const std::string ctx = context(s, base);
    Ray r = base;
    ASSERT_TRUE(s.has_intersection(r)) << "has_intersection missed.\n" << ctx;
    ASSERT_TRUE(range_unchanged("has_intersection", r, base)) << "\n" << ctx;
    Intersection isect = before;
    ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed.\n" << ctx;
    EXPECT_TRUE(Near("isect.t", isect.t, t, kTol)) << "\n" << ctx;
    EXPECT_TRUE(VecNear("isect.n", isect.n, (base.at(t) - s.o) / s.r, 1e-9)) << "\n" << ctx;
    EXPECT_TRUE(VecNear("isect.barycentric", isect.barycentric, Vec3(0.0), 0.0))
        << "\nA sphere has no barycentric weights: set them to 0, or they stay as an earlier triangle hit wrote them "
           "("
        << before.barycentric << " here).\n"
        << ctx;
    EXPECT_EQ(isect.primitive, &s) << "isect.primitive after a hit on this sphere\n" << ctx;
    EXPECT_EQ(isect.bsdf, s.get_bsdf()) << "isect.bsdf after a hit on this sphere\n" << ctx;
    EXPECT_EQ(r.max_t, isect.t) << "r.max_t after the hit\n" << ctx;
    EXPECT_EQ(r.min_t, base.min_t) << "r.min_t after the hit\n" << ctx;
    if (testing::Test::HasFailure()) return;
    // Misses: the range ends before the hit; the sphere behind; a line past it.
    Ray short_ray = base;
    short_ray.max_t = 0.99 * t;
    const Ray behind(base.o, -base.d), past(s.o + 1.01 * s.r * a.p - a.D * a.u, a.u);
    for (const Ray& miss : {short_ray, a.D > s.r ? behind : short_ray, past})
      EXPECT_TRUE(miss_changes_nothing(s, miss, before)) << "\n" << context(s, miss);
  }
}

GRADED_TEST(SphereIntersect, HasIntersectionAgreesWithIntersect, "P1T4", 0.5, Visible) {
  Rng rng(seed(0x5e2));
  for (int k = 0; k < 2000; ++k) {
    RandomSphereCase c = random_sphere_case(rng, k % 2 == 1);
    Ray r1 = c.ray, r2 = c.ray;
    Intersection isect;
    bool any = c.sphere.has_intersection(r1);
    ASSERT_EQ(any, c.sphere.intersect(r2, &isect))
        << "has_intersection and intersect disagree (random ray " << k << ").\n"
        << context(c.sphere, c.ray);
  }
}

}  // namespace
}  // namespace pt::test::part1
