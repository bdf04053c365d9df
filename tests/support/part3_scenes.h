#pragma once
// Scenes of the Part 3 tests, built in code so that every number is known:
// a small diffuse "receiver" square at a point p with normal n, lights and
// occluders around it, and a ray that hits the receiver at p.
#include <stdexcept>
#include <vector>

#include "core/ray.h"
#include "geometry/intersection.h"
#include "scene/scene.h"
#include "support/part3_closed_forms.h"
#include "support/scene_builders.h"

namespace pt::test::part3 {

using test::Aim;  // support/scene_builders.h

// Side of the receiver square: small enough to shadow nothing the tests
// light it with (every light and occluder is at least 0.1 away from it).
constexpr double kReceiverSize = 0.02;

// Adds the receiver: a diffuse square of the given albedo (and emission,
// none unless given) around p, facing n (a quad whose cross(ex, ey) is n).
// Call before scene.build().
inline const BSDF* add_receiver(Scene& s, const Vec3& p, const Vec3& n, const Spectrum& albedo,
                                const Spectrum& emission = Spectrum(0.0)) {
  const Vec3 nn = glm::normalize(n);
  const Vec3 a = std::abs(nn.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 ex = glm::normalize(glm::cross(a, nn)) * kReceiverSize;
  const Vec3 ey = glm::cross(nn, ex);  // cross(ex, ey) is along n
  const BSDF* b = s.add_bsdf<DiffuseBSDF>(albedo, emission);
  // Off-centre, so that p lies inside one triangle, away from the diagonal
  // the quad's two triangles share (where a hit is a matter of rounding).
  s.add_quad(p + 0.15 * ex - 0.1 * ey, ex, ey, b);
  return b;
}

// A ray and the intersection the estimators take: the ray starts 0.005 from
// p on the front side (at 30 degrees from the normal) and hits the receiver
// at p. The scene must be built.
inline Aim aim_at(const Scene& s, const Vec3& p, const Vec3& n) {
  const Vec3 nn = glm::normalize(n);
  const Vec3 a = std::abs(nn.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 tangent = glm::normalize(glm::cross(a, nn));
  const Vec3 from = p + 0.005 * glm::normalize(nn + 0.577 * tangent);
  Aim aim;
  aim.ray = Ray(from, glm::normalize(p - from));
  if (!s.intersect(aim.ray, &aim.isect)) throw std::logic_error("test set-up: the aiming ray misses the receiver");
  return aim;
}

// Receivers under one parallelogram light (edges ex, ey; cross(ex, ey) is
// the emitting side), with the irradiance the closed form gives. Used by the
// graded mean tests and checked against brute force by the framework tests.
struct LambertCase {
  const char* name;
  Vec3 p, n, c, ex, ey;
};

inline std::vector<LambertCase> lambert_cases() {
  const Vec3 c0(0, 0, 1), ex0(0.8, 0, 0), ey0(0, -0.6, 0);  // 0.8 x 0.6 at height 1, facing down
  return {
      {"below the centre", {0, 0, 0}, {0, 0, 1}, c0, ex0, ey0},
      {"offset, tilted normal", {0.7, -0.3, 0.2}, glm::normalize(Vec3(-0.3, 0.2, 1)), c0, ex0, ey0},
      {"partly below the horizon", {0.2, 0, 0.5}, {1, 0, 0}, c0, ex0, ey0},
      {"mostly below the horizon", {0.35, 0.1, 0.3}, glm::normalize(Vec3(1, 0.2, 0.3)), c0, ex0, ey0},
      {"far and grazing", {2, 0.5, 0.3}, glm::normalize(Vec3(-1, 0, 0.2)), c0, ex0, ey0},
      {"tilted light", {0.1, -0.2, 0}, {0, 0, 1}, {0.5, 0.5, 1.2}, {0, 0.5, 0.2}, {0.6, 0, 0.3}},
      {"wholly below the horizon", {0, 0, 0.5}, {0, 0, -1}, c0, ex0, ey0},
      {"behind the light", {0, 0, 1.5}, {0, 0, -1}, c0, ex0, ey0},
  };
}

// An opaque black quad at height 0.5 covering x in [edge_x, edge_x + 3],
// y in [-2, 2], between the light of lambert_cases() (height 1) and points
// near the origin below it. Its edge x = edge_x cuts the light as seen from
// p along the plane through p and the edge (visible_past_edge); when that
// plane meets the light's plane beyond x = 0.4 the occluder is "beside" the
// paths to the light and must cast no shadow at all.
struct EdgeOccluder {
  double edge_x;
  Vec3 center() const { return {edge_x + 1.5, 0, 0.5}; }
  void add_to(Scene& s) const { s.add_quad(center(), {3, 0, 0}, {0, 4, 0}, s.add_bsdf<DiffuseBSDF>(Spectrum(0.0))); }
  // The part of the parallelogram light (c, ex, ey) that p sees.
  Polygon visible(const Vec3& p, const Vec3& c, const Vec3& ex, const Vec3& ey) const {
    return visible_past_edge(parallelogram(c, ex, ey), p, {edge_x, -2, 0.5}, {edge_x, 2, 0.5}, center());
  }
};

struct OccluderCase {
  const char* name;
  Vec3 p, n;
  EdgeOccluder occluder;
  bool blocks;  // false: beside the paths, no shadow
};

// Under the 0.8 x 0.6 light of lambert_cases() (centre (0, 0, 1)).
inline std::vector<OccluderCase> occluder_cases() {
  const Vec3 n = glm::normalize(Vec3(0.1, 0.05, 1));
  return {
      {"edge cuts the light, below the centre", {0, 0, 0}, n, {0.1}, true},
      {"edge cuts the light, offset point", {0.3, -0.1, 0.1}, n, {0.1}, true},
      {"occluder beside the paths, below the centre", {0, 0, 0}, n, {0.22}, false},  // edge maps to x = 0.44
      {"occluder beside the paths, offset point", {0.3, -0.1, 0.1}, n, {0.36}, false},  // x = 0.435
  };
}

}  // namespace pt::test::part3
