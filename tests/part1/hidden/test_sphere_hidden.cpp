// Hidden P1T4 tests: spheres far smaller and larger than 1, random rays
// against the closed form.
#include <algorithm>
#include <sstream>

#include "../sphere_cases.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt::test::part1 {
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

GRADED_TEST(SphereIntersect, HitsExactlyAtTheEndsOfTheRange, "P1T4", 0.5, Hidden) {
  // The interval is closed. Spheres whose roots every formulation computes
  // exactly (small integers: the quadratic, its stable form, the closest
  // approach; directions along an axis with lengths that are powers of two):
  // roots 4 and 6 for the unit sphere 5 ahead. A range that ends exactly on a
  // root must count it: [4, 5] and [0, 4] hit at 4, [4.5, 6] and [6, 6] at 6,
  // [4, 4] at 4; after intersect has set max_t = 4 the ray still hits. A
  // strict comparison on either end fails; no correct solution can
  // (boundary: exactly on the root).
  struct Exact {
    Vec3 centre;
    double radius;
    Vec3 o, d;
    double t1, t2;
  };
  const Exact spheres[] = {{{0, 0, -5}, 1.0, {0, 0, 0}, {0, 0, -1}, 4, 6},
                           {{3, 1, 2}, 2.0, {0, 1, 2}, {0.5, 0, 0}, 2, 10},  // x = 1 and 5, in units of |d| = 0.5
                           {{1, -8, 0}, 0.5, {1, 0, 0}, {0, -4, 0}, 1.875, 2.125}};
  for (const Exact& e : spheres) {
    Sphere s(e.centre, e.radius, &g_bsdf);
    const Vec3& o = e.o;
    struct Range {
      double min_t, max_t, t;
    };
    const double mid = 0.5 * (e.t1 + e.t2);
    const Range ranges[] = {{e.t1, mid, e.t1},  {0.0, e.t1, e.t1},   {0.5 * (e.t1 + mid), e.t2, e.t2},
                            {e.t2, e.t2, e.t2}, {e.t1, e.t1, e.t1}, {e.t2, kInf, e.t2}};
    for (const Range& rg : ranges) {
      Ray r(o, e.d);
      r.min_t = rg.min_t;
      r.max_t = rg.max_t;
      std::ostringstream why = stream15();
      why << "Roots " << e.t1 << " and " << e.t2 << " (exact), t range [" << rg.min_t << ", " << rg.max_t
          << "]: a root on an end of the interval counts (min_t <= t <= max_t), the hit is at t = " << rg.t << ".\n"
          << context(s, r);
      EXPECT_TRUE(s.has_intersection(r)) << "has_intersection missed. " << why.str();
      Intersection isect;
      ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed. " << why.str();
      EXPECT_TRUE(Near("isect.t", isect.t, rg.t, kTol)) << "\n" << why.str();
    }
    Ray r(o, e.d);
    Intersection isect;
    ASSERT_TRUE(s.intersect(r, &isect)) << "intersect missed.\n" << context(s, Ray(o, e.d));
    std::ostringstream again = stream15();
    again << "intersect hit at t = " << isect.t << " and set max_t = " << r.max_t
          << "; the same ray, tested again, must still hit there.\n"
          << context(s, r);
    EXPECT_TRUE(s.has_intersection(r)) << "has_intersection missed. " << again.str();
    EXPECT_TRUE(s.intersect(r, &isect)) << "intersect missed. " << again.str();
  }
}

GRADED_TEST(SphereTest, TangentRayFromAPointOnTheSphere, "P1T4", 0.5, Hidden) {
  // The case section 4 of the handout names: the origin on the sphere, the
  // direction tangent to it (a ray leaving a sphere's silhouette). Then
  // b = 2 (o - c).d = 0 and c = |o - c|^2 - r^2 = 0, exactly, in every
  // formulation (small dyadic numbers): the discriminant is 0 and both roots
  // are 0. The stable form's q = -(b + sign(b) sqrt(disc)) / 2 is 0 there,
  // and c / q is 0 / 0: a solution that divides without the q = 0 case
  // returns NaN. test() must give t1 = t2 = 0; the ray touches the sphere at
  // its origin, a hit for min_t = 0 (t = 0, outward normal) and a miss once
  // min_t > 0 (a shadow ray offset by an epsilon does not see the sphere it
  // leaves). Boundary: the exact double root 0.
  struct Case {
    Vec3 centre;
    double radius;
    Vec3 o, d;
  };
  const Case cases[] = {{{0, 0, 0}, 1.0, {1, 0, 0}, {0, 1, 0}},
                        {{1, 2, 3}, 2.0, {3, 2, 3}, {0, 0, 5}},
                        {{-1, 0.5, 2}, 0.5, {-1, 1, 2}, {3, 0, -4}}};
  for (const Case& c : cases) {
    Sphere s(c.centre, c.radius, &g_bsdf);
    Ray r(c.o, c.d);
    const std::string ctx = context(s, r);
    double t1 = -1, t2 = -1;
    ASSERT_TRUE(s.test(r, t1, t2)) << "test(): the ray is tangent at its origin, a double root at 0.\n" << ctx;
    EXPECT_TRUE(Near("t1", t1, 0.0, 1e-12) && Near("t2", t2, 0.0, 1e-12))
        << "t1 = " << t1 << ", t2 = " << t2
        << ", expected 0 and 0: b = 0 and c = 0 here, so q = 0 in the stable form and c / q is 0 / 0; "
           "handle q = 0 (both roots 0)\n"
        << ctx;
    Ray from_zero = r;
    from_zero.min_t = 0.0;
    EXPECT_TRUE(s.has_intersection(from_zero)) << "has_intersection with min_t = 0: the root t = 0 is in range.\n"
                                               << ctx;
    Intersection isect;
    ASSERT_TRUE(s.intersect(from_zero, &isect)) << "intersect with min_t = 0: the root t = 0 is in range.\n" << ctx;
    EXPECT_TRUE(Near("isect.t", isect.t, 0.0, 1e-12)) << "\n" << ctx;
    EXPECT_TRUE(VecNear("isect.n", isect.n, (c.o - c.centre) / c.radius, 1e-9)) << "\n" << ctx;
    Ray offset = r;
    offset.min_t = 1e-5;
    EXPECT_FALSE(s.has_intersection(offset)) << "has_intersection with min_t = 1e-5: both roots are 0.\n" << ctx;
    Intersection none;
    EXPECT_FALSE(s.intersect(offset, &none)) << "intersect with min_t = 1e-5: both roots are 0.\n" << ctx;
    EXPECT_EQ(offset.max_t, kInf) << "A miss must leave max_t alone.\n" << ctx;
  }
}

GRADED_TEST(SphereTest, OriginOnTheSphereHeadingIn, "P1T4", 0.5, Hidden) {
  // A ray that starts on the sphere and heads into it (a ray leaving the
  // surface inwards, or one started there by an epsilon too small to move
  // it) has the roots 0 and the exit. The stable form takes the root whose
  // terms do not cancel first: q = -(b + sign(b) sqrt(disc)) / 2. Written the
  // other way round, q = -(b - sign(b) sqrt(disc)) / 2 is the CANCELLING
  // root: here c = 0, so sqrt(disc) = |b| and that q is exactly 0, both roots
  // come out 0 (or c / q = 0 / 0 = NaN) and the exit is lost.
  // (a) Origins exactly on the sphere (|o - c| = r in small dyadic numbers,
  //     so c = 0 exactly in every formulation): test() gives t1 = 0 and
  //     t2 = -b / a = -2 (o - c).d / (d.d); with min_t = 1e-5 the hit is the
  //     exit (outward normal), with min_t = 0 it is t = 0. Tolerance 1e-12
  //     relative: the textbook formula and the stable form are exact here.
  struct OnSphere {
    Vec3 centre;
    double radius;
    Vec3 offset, d;  // origin = centre + offset, |offset| = radius
  };
  const OnSphere on[] = {{{1, 2, 3}, 2.0, {2, 0, 0}, {-3, 1, 2}},
                         {{0, 0, 0}, 5.0, {3, 4, 0}, {-1, -2, 0.5}},
                         {{-1, 0.5, 2}, 0.625, {0, 0.375, -0.5}, {0.25, -1, 1}},
                         {{0, 0, -1e4}, 1e4, {6e3, 0, 8e3}, {-0.6, 0.1, -0.8}}};
  for (const OnSphere& c : on) {
    Sphere s(c.centre, c.radius, &g_bsdf);
    Ray r(c.centre + c.offset, c.d);
    const std::string ctx = context(s, r);
    const double exit = -2.0 * glm::dot(c.offset, c.d) / glm::dot(c.d, c.d);
    std::ostringstream why = stream15();
    why << "The origin is on the sphere (|o - c| = r exactly, so c = |o - c|^2 - r^2 = 0) and the ray heads "
           "into it: the roots are 0 and the exit "
        << exit
        << ". In the stable form q = -(b + sign(b) sqrt(disc)) / 2 (sign(b) with a plus: the terms that do not "
           "cancel); with a minus q is 0 here and the exit is lost.\n"
        << ctx;
    double t1 = -1, t2 = -1;
    ASSERT_TRUE(s.test(r, t1, t2)) << "test() found no roots. " << why.str();
    EXPECT_TRUE(Near("t1", t1, 0.0, 1e-12 * c.radius)) << "\n" << why.str();
    EXPECT_TRUE(Near("t2", t2, exit, 1e-12 * exit)) << "\n" << why.str();
    Ray offset = r;
    offset.min_t = 1e-5;
    EXPECT_TRUE(s.has_intersection(offset)) << "has_intersection with min_t = 1e-5 missed. " << why.str();
    Intersection isect;
    ASSERT_TRUE(s.intersect(offset, &isect)) << "intersect with min_t = 1e-5 missed. " << why.str();
    EXPECT_TRUE(Near("isect.t", isect.t, exit, 1e-12 * exit)) << "\n" << why.str();
    EXPECT_TRUE(VecNear("isect.n", isect.n, (r.at(exit) - c.centre) / c.radius, 1e-9)) << "\n" << why.str();
    Ray from_zero = r;
    Intersection at_origin;
    ASSERT_TRUE(s.intersect(from_zero, &at_origin)) << "intersect with min_t = 0 missed (t = 0 is a root). "
                                                    << why.str();
    EXPECT_TRUE(Near("isect.t", at_origin.t, 0.0, 1e-12 * c.radius)) << "\n" << why.str();
  }
  // (b) A sphere of radius 1e4 (a floor modelled as a sphere), the
  //     origin 1e-5 inside its surface, heading in along the inward normal
  //     and 60 degrees off it: the near root is about -1e-5, the hit is the
  //     exit, (r - e) cos + sqrt((r - (r - e) sin) (r + (r - e) sin)) with
  //     e = 1e-5 (factored so that the closed form itself does not cancel).
  //     Measured errors of the exit: the textbook formula and the stable form
  //     3.2e-12 or less; the cancelling root first 6.8e-4 and 1.0e-4. Tolerance
  //     1e-5 (1e-9 of the radius): 3000x above the first, 10x below the second.
  const double R = 1e4, e = 1e-5;
  Sphere big(Vec3(0, 0, 0), R, &g_bsdf);  // centred at the origin: o - c is o, exactly
  for (double angle : {0.0, 60.0}) {
    const double cs = std::cos(glm::radians(angle)), sn = std::sin(glm::radians(angle));
    Ray r(Vec3(0, 0, R - e), Vec3(0, sn, -cs));  // the inward normal is -z
    const double exit = (R - e) * cs + std::sqrt((R - (R - e) * sn) * (R + (R - e) * sn));
    std::ostringstream why = stream15();
    why << "The origin is " << e << " inside the surface of a sphere of radius " << R << ", the ray " << angle
        << " degrees off the inward normal: the hit is the exit at t = " << exit
        << ", tolerance 1e-5 (a correct formulation is within 4e-12; computing the cancelling root first, "
           "q = -(b - sign(b) sqrt(disc)) / 2, and the exit as c / q loses it).\n"
        << context(big, r);
    Intersection isect;
    ASSERT_TRUE(big.intersect(r, &isect)) << "intersect missed. " << why.str();
    EXPECT_TRUE(Near("isect.t", isect.t, exit, 1e-9 * R)) << "\n" << why.str();
    double t1 = 0, t2 = 0;
    ASSERT_TRUE(big.test(Ray(r.o, r.d), t1, t2)) << "test() found no roots. " << why.str();
    EXPECT_TRUE(Near("t2", t2, exit, 1e-9 * R)) << "\n" << why.str();
  }
}

}  // namespace
}  // namespace pt::test::part1
