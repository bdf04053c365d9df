#pragma once
// Spheres and rays shared by the Part 1 sphere tests (P1T4). Rays are placed
// by their closest approach to the centre: a ray with unit direction u that
// passes at distance h from the centre c, reaching its closest point after a
// distance D, has roots D -+ sqrt(r^2 - h^2).
#include <cmath>
#include <sstream>
#include <string>

#include "support/part1_builders.h"

namespace pt::test::part1 {

// A ray with unit direction u whose closest approach to the sphere's centre
// is the point c + h p (p a unit vector orthogonal to u), reached at t = D.
struct Approach {
  Vec3 u, p;
  double D, h;
};

// Unit vector orthogonal to u, in a direction that depends on `angle`.
inline Vec3 orthogonal(const Vec3& u, double angle) {
  Vec3 a = std::abs(u.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  Vec3 e1 = glm::normalize(glm::cross(u, a)), e2 = glm::cross(u, e1);
  return std::cos(angle) * e1 + std::sin(angle) * e2;
}

inline Approach approach(const Vec3& dir, double D, double h, double angle = 0.7) {
  Vec3 u = glm::normalize(dir);
  return {u, orthogonal(u, angle), D, h};
}

inline Ray ray_past(const Sphere& s, const Approach& a) { return Ray(s.o + a.h * a.p - a.D * a.u, a.u); }

// The closed-form roots of that ray.
inline double near_root(const Sphere& s, const Approach& a) { return a.D - std::sqrt(s.r * s.r - a.h * a.h); }
inline double far_root(const Sphere& s, const Approach& a) { return a.D + std::sqrt(s.r * s.r - a.h * a.h); }

// The sphere and the ray as given (call before the ray's max_t changes).
inline std::string context(const Sphere& s, const Ray& r) {
  std::ostringstream os = stream15();
  os << describe(s) << "\nray " << r;
  return os.str();
}

inline DiffuseBSDF g_bsdf{Spectrum(0.5)};

// A random sphere and a ray aimed near it (about half the rays hit), with a
// random non-unit direction and sometimes a random t range.
struct RandomSphereCase {
  Sphere sphere;
  Ray ray;
};
inline RandomSphereCase random_sphere_case(Rng& rng, bool random_range) {
  auto u = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  auto v = [&](double lo, double hi) { return Vec3(u(lo, hi), u(lo, hi), u(lo, hi)); };
  Sphere s(v(-2, 2), u(0.1, 2.0), &g_bsdf);
  Vec3 o = rng.uniform() < 0.2 ? s.o + v(-0.5, 0.5) * s.r : v(-6, 6);
  Vec3 target = s.o + v(-1.5, 1.5) * s.r;
  Ray r(o, (target - o) * u(0.2, 3.0));
  if (random_range) {
    r.min_t = u(0.0, 1.0);
    r.max_t = u(0.5, 2.0);
  }
  return {s, r};
}

}  // namespace pt::test::part1
