#pragma once
// Triangles and rays shared by the Part 1 triangle tests (P1T3). Rays are
// built to reach a chosen point (barycentric weights w1, w2, w3 of p1, p2, p3)
// at a chosen t, so hit distance, point, barycentrics and interpolated normal
// are known in closed form.
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "support/part1_builders.h"

namespace pt::test::part1 {

// A triangle in general position with three different vertex normals.
inline std::unique_ptr<TriangleSet> general_triangle() {
  auto s = std::make_unique<TriangleSet>();
  s->add(Vec3(0.3, -0.2, 1.0), Vec3(2.1, 0.4, -0.5), Vec3(-0.7, 1.8, 0.2), glm::normalize(Vec3(1.0, 0.2, 0.5)),
         glm::normalize(Vec3(-0.3, 1.0, 0.4)), glm::normalize(Vec3(0.1, -0.2, 1.0)));
  return s;
}

// Hit cases on the general triangle: weights, direction (not all unit
// length, not all from the same side) and the distance to the hit.
struct HitCase {
  double w1, w2, w3;
  Vec3 d;
  double t;
};
inline const std::vector<HitCase> kHits = {
    {0.2, 0.3, 0.5, glm::normalize(Vec3(-0.2, -0.3, -1.0)), 2.5},
    {0.6, 0.1, 0.3, glm::normalize(Vec3(1.0, 0.5, -0.2)), 1.25},
    {1.0 / 3, 1.0 / 3, 1.0 / 3, glm::normalize(Vec3(0.1, -1.0, 0.3)), 7.0},
    {0.05, 0.9, 0.05, Vec3(0.5, 1.0, 2.5), 0.8},  // |d| != 1: t is in units of d
    {0.7, 0.05, 0.25, glm::normalize(Vec3(-1.0, -1.0, -1.0)), 3.0},
};

// The triangle and the ray as given (call before the ray's max_t changes).
inline std::string context(const Triangle& tri, const Ray& r, const HitCase* c = nullptr) {
  std::ostringstream os = stream15();
  os << describe(tri) << "\nray " << r;
  if (c)
    os << "\n(the ray was built to reach weights (" << c->w1 << ", " << c->w2 << ", " << c->w3 << ") at t = " << c->t
       << ")";
  return os.str();
}

// Random triangle and a ray aimed near it: about half the rays hit.
struct RandomTriangleCase {
  std::unique_ptr<TriangleSet> set;
  Ray ray;
};
inline RandomTriangleCase random_triangle_case(Rng& rng, bool random_range) {
  auto u = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  auto v = [&](double lo, double hi) { return Vec3(u(lo, hi), u(lo, hi), u(lo, hi)); };
  RandomTriangleCase c{std::make_unique<TriangleSet>(), Ray()};
  const Triangle& tri = c.set->add(v(-1, 1), v(-1, 1), v(-1, 1));
  double w2 = u(-0.4, 1.2), w3 = u(-0.4, 1.2);
  Vec3 target = (1 - w2 - w3) * tri.p1() + w2 * tri.p2() + w3 * tri.p3();
  Vec3 o = v(-4, 4);
  c.ray = Ray(o, (target - o) * u(0.2, 3.0));  // not unit length
  if (random_range) {
    c.ray.min_t = u(0.0, 0.8);
    c.ray.max_t = u(0.5, 2.0);
  }
  return c;
}

}  // namespace pt::test::part1
