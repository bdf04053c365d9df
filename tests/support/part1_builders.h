#pragma once
// Builders and checks shared by the Part 1 tests (tests/part1/). Every expected
// value in those tests is a closed form computed here or in the test itself,
// never a number copied from the reference's output.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "core/ray.h"
#include "core/rng.h"
#include "geometry/intersection.h"
#include "geometry/mesh.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "support/assertions.h"

namespace pt::test::part1 {

// Hit distances, points and normals of O(1) geometry come from a few dozen
// flops: 1e-9 is generous for any formulation and far below any real mistake.
constexpr double kTol = 1e-9;

// A string stream printing 15 significant digits: enough to reproduce a
// failing input, few enough that 0.3 still prints as 0.3.
inline std::ostringstream stream15() {
  std::ostringstream os;
  os.precision(15);
  return os;
}

// ----------------------------------------------------------------- camera --

// A camera given by its look-at parameters, as in a scene file.
struct LookAt {
  Vec3 pos, target, up;
  double hfov, vfov;  // degrees
};

inline Camera make_camera(const LookAt& c, double near_clip = 1e-4, double far_clip = 1e30) {
  return Camera(c.pos, c.target, c.up, c.hfov, c.vfov, near_clip, far_clip);
}

// Closed form of generate_ray(x, y), from the look-at parameters and not from
// Camera::c2w: the camera's frame (forward = the view axis, right, up), then
// the point of the sensor plane one unit along forward, offset by
// (2x - 1) tan(hfov/2) along right and (2y - 1) tan(vfov/2) along up, normalised.
inline Vec3 expected_direction(const LookAt& c, double x, double y) {
  Vec3 forward = glm::normalize(c.target - c.pos);
  Vec3 right = glm::normalize(glm::cross(forward, c.up));
  Vec3 up = glm::cross(right, forward);
  double tx = std::tan(glm::radians(c.hfov) / 2.0), ty = std::tan(glm::radians(c.vfov) / 2.0);
  return glm::normalize(forward + (2.0 * x - 1.0) * tx * right + (2.0 * y - 1.0) * ty * up);
}

// -------------------------------------------------------------- triangles --

// One or more triangles over a mesh they own. Not movable: Triangle keeps a
// pointer to the mesh.
struct TriangleSet {
  TriangleSet() = default;
  TriangleSet(const TriangleSet&) = delete;
  TriangleSet& operator=(const TriangleSet&) = delete;

  Mesh mesh;
  DiffuseBSDF bsdf{Spectrum(0.5)};
  std::vector<std::unique_ptr<Triangle>> tris;

  // Adds triangle (a, b, c) with vertex normals (na, nb, nc); returns it.
  const Triangle& add(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& na, const Vec3& nb, const Vec3& nc) {
    uint32_t i = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.normals.insert(mesh.normals.end(), {na, nb, nc});
    mesh.faces.push_back({i, i + 1, i + 2});
    mesh.bsdf = &bsdf;
    tris.push_back(std::make_unique<Triangle>(&mesh, i, i + 1, i + 2));
    return *tris.back();
  }
  // Flat triangle: every vertex normal is the geometric normal (or +z when
  // the triangle is degenerate).
  const Triangle& add(const Vec3& a, const Vec3& b, const Vec3& c) {
    Vec3 n = glm::cross(b - a, c - a);
    n = glm::length(n) > 0.0 ? glm::normalize(n) : Vec3(0.0, 0.0, 1.0);
    return add(a, b, c, n, n, n);
  }
};

// Describes a triangle in failure messages.
inline std::string describe(const Triangle& t) {
  std::ostringstream os = stream15();
  os << "triangle{p1=" << t.p1() << " p2=" << t.p2() << " p3=" << t.p3() << " n1=" << t.n1() << " n2=" << t.n2()
     << " n3=" << t.n3() << "}";
  return os.str();
}

inline std::string describe(const Sphere& s) {
  std::ostringstream os = stream15();
  os << "sphere{centre=" << s.o << " radius=" << s.r << "}";
  return os.str();
}

// A ray that reaches the point with barycentric weights (w1, w2, w3) of the
// triangle at exactly t = t_hit along direction d.
inline Ray ray_to(const Triangle& tri, double w1, double w2, double w3, const Vec3& d, double t_hit) {
  Vec3 p = w1 * tri.p1() + w2 * tri.p2() + w3 * tri.p3();
  return Ray(p - t_hit * d, d);
}

// ---------------------------------------------------------------- spheres --

// Closed-form roots of a ray against a sphere, computed from the ray's closest
// approach to the centre: with a unit direction u, the centre is at distance
// D = (c - o).u along the ray and h = |c - o - D u| from it; the roots are
// D -+ sqrt(r^2 - h^2), divided by |d| for a ray of direction d = |d| u.
struct Roots {
  bool real;
  double t1, t2;
  double h;  // distance of the line from the centre
};

inline Roots closest_approach_roots(const Vec3& o, const Vec3& d, const Vec3& c, double r) {
  double len = glm::length(d);
  Vec3 u = d / len;
  double D = glm::dot(c - o, u);
  Vec3 perp = (c - o) - D * u;
  double h2 = glm::dot(perp, perp);
  if (h2 > r * r) return {false, 0.0, 0.0, std::sqrt(h2)};
  double s = std::sqrt(r * r - h2);
  return {true, (D - s) / len, (D + s) / len, std::sqrt(h2)};
}

}  // namespace pt::test::part1
