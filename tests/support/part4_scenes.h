#pragma once
// Scenes of the Part 4 tests, built in code so that every number is known.
//
//   make_white_furnace   a closed box whose every wall reflects (albedo a) and
//                        emits (radiance Le): the radiance of the k-th bounce
//                        alone is Le a^k everywhere, whatever the geometry.
//   make_mirror_chain    a zig-zag of "normal mirrors" ending at a diffuse
//                        card lit by a point light: light reaches the eye
//                        after exactly mirrors + 1 bounces and no fewer, and
//                        the estimate is deterministic (no noise at all).
//
// Both count the BSDF samples of one path (PathGuard) and stop a runaway path
// with an exception that says so, instead of a stack overflow or a hang: a
// path that never decrements its depth ends in a clear test failure.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/ray.h"
#include "geometry/intersection.h"
#include "scene/path_guard.h"
#include "scene/scene.h"
#include "support/scene_builders.h"

namespace pt::test::part4 {

using test::Aim;  // support/scene_builders.h

// ---------------------------------------------------------------------------
// Path guard

// The guard and the BSDFs that count in it are the framework's
// (scene/path_guard.h), so that the grader's worker rebuilds the same ones.
// A correct estimator samples a BSDF at most once per path vertex, i.e. at
// most max_ray_depth times per camera path (it has no reason to sample at the
// last vertex, and may); with Russian roulette of continuation probability
// p < 1, a path also survives k bounces past the first only with probability
// p^k. See guard_limit.
using pt::GuardedDiffuse;
using pt::NormalMirror;
using pt::path_guard;
using pt::PathGuard;

// The limit for an estimate with max_ray_depth = m and continuation
// probability p: twice what a correct solution may take (2 m + 2), capped at
// 4000; and with p < 1 also at 12 + log(1e-13) / log(p) (56 for p = 0.5, 96
// for p = 0.7, 297 for p = 0.9, 596 for p = 0.95), a length that a path under
// roulette exceeds with probability below p^10 * 1e-13: over the fewer than
// 1e6 estimates a test takes per configuration, a correct solution trips the
// guard with probability below 1e-7, even if its roulette starts a few
// bounces late. A solution without roulette trips it on its first estimate,
// instead of tracing thousands of bounces per path.
inline int64_t guard_limit(int max_ray_depth, double rr_continue_prob = 1.0) {
  int64_t limit = std::min<int64_t>(2 * int64_t(max_ray_depth) + 2, 4000);
  if (rr_continue_prob < 1.0 && rr_continue_prob > 0.0)
    limit = std::min<int64_t>(limit, 12 + int64_t(std::ceil(std::log(1e-13) / std::log(rr_continue_prob))));
  return limit;
}

inline std::string guard_reason(int max_ray_depth, double rr_continue_prob) {
  std::ostringstream os;
  os << "max_ray_depth " << max_ray_depth << ", rr_continue_prob " << rr_continue_prob;
  return os.str();
}

// ---------------------------------------------------------------------------
// White furnace

// The box [-1, 1]^3; every wall faces inwards (cross(ex, ey) points in).
struct Wall {
  Vec3 c, ex, ey;
};
inline const Wall (&furnace_walls())[6] {
  static const Wall walls[6] = {
      {{0, -1, 0}, {0, 0, 2}, {2, 0, 0}},  // floor, +y
      {{0, 1, 0}, {2, 0, 0}, {0, 0, 2}},   // ceiling, -y
      {{0, 0, -1}, {2, 0, 0}, {0, 2, 0}},  // back, +z
      {{0, 0, 1}, {0, 2, 0}, {2, 0, 0}},   // front, -z
      {{-1, 0, 0}, {0, 2, 0}, {0, 0, 2}},  // left, +x
      {{1, 0, 0}, {0, 0, 2}, {0, 2, 0}},   // right, -x
  };
  return walls;
}

// The white furnace: a closed box, every wall Lambertian of albedo `albedo`
// and emitting radiance `Le` inwards (one-sided). Every ray from inside hits
// a wall's front, so the radiance along any ray inside is
//   L = Le + a L  =>  L = Le / (1 - a),
// and bounce k alone (light reflected exactly k times) carries Le a^k: the
// k-th vertex's direct light is a Le, and each of the k - 1 bounces before it
// has weight f cos / pdf = (a / pi) cos / (cos / pi) = a exactly.
//
// The walls emit but are not in the light list: direct light must be found by
// hemisphere sampling (settings.direct_hemisphere_sample), which here is a
// bounded estimator (0 <= f cos / pdf * Le <= 2 a Le). Were the walls also
// area lights, light sampling at a point near the edge where two walls meet
// would sample the other wall at distances r -> 0 with weight ~ cos cos' /
// r^2: the estimator of bounce >= 2 would have infinite variance (tail
// P(X > x) ~ x^-1.5), its mean still right but no t-test on it able to
// promise a false-failure rate.
inline Scene make_white_furnace(double albedo, double Le) {
  Scene s;
  const BSDF* wall = s.add_bsdf<GuardedDiffuse>(Spectrum(albedo), Spectrum(Le));
  for (const Wall& w : furnace_walls()) {
    s.add_quad(w.c, w.ex, w.ey, wall);
  }
  s.camera = Camera({0.1, -0.2, 0.3}, {0.3, 0.0, -0.7}, {0, 1, 0}, 60.0, 60.0);
  s.build();
  return s;
}

// A ray from inside the furnace (off-centre, in a general direction) and the
// wall point it hits, well inside the back wall (away from every edge).
inline Aim aim(const Scene& s, const Vec3& from, const Vec3& dir) {
  Aim a;
  a.ray = Ray(from, glm::normalize(dir));
  if (!s.intersect(a.ray, &a.isect)) throw std::logic_error("test set-up: the aiming ray hits nothing");
  a.ray.max_t = kInf;  // the query shrank it; the estimators get the ray as a camera would give it
  return a;
}

inline Aim furnace_aim(const Scene& s) { return aim(s, {0.1, -0.2, 0.3}, {0.2, 0.2, -1.0}); }

// ---------------------------------------------------------------------------
// Mirror chain

// NormalMirror (scene/path_guard.h): all light along the surface normal,
// f cos / pdf = 1 exactly, and direct light at a mirror exactly zero.

// mirrors >= 1 normal mirrors at P_1 .. P_mirrors on a zig-zag in the y = 0
// plane, P_k = (0.5 k, 0, k odd ? 0 : 1), each 0.2 x 0.2 and facing P_{k+1}
// (so it reflects the ray from P_{k-1} on to P_{k+1}; the angle at each
// corner is 53 degrees, so every hit is on a front side), and at
// P_{mirrors+1} a diffuse card (albedo 0.5) facing back along the chain, lit
// by a point light of intensity 2 off the plane. A camera ray from
// P_0 = (0, 0, 1) to P_1 starts the chain.
//
// Light reaches the eye only as the card's direct light, and the card is
// vertex mirrors + 1 of every path: that light has bounced exactly
// mirrors + 1 times. With max_ray_depth = d the estimate is therefore
//   exactly 0                              for d <= mirrors,
//   exactly card_radiance (no noise)       for d  = mirrors + 1 (p = 1),
// and with accumulate_bounces off, bounce k alone is card_radiance for
// k = mirrors + 1 and exactly 0 for k <= mirrors. (Beyond mirrors + 1 the
// card's own bounce ray may come back along the chain: the tests stop there.)
struct MirrorChain {
  Scene scene;
  Aim first;              // the camera ray and its hit on the first mirror
  double card_radiance;   // radiance the card reflects towards the last mirror
  int mirrors;
};

inline Vec3 chain_point(int k) { return {0.5 * k, 0.0, k % 2 == 1 ? 0.0 : 1.0}; }

// A square of side `size` centred at c facing n (cross(ex, ey) along n).
inline void add_facing_quad(Scene& s, const Vec3& c, const Vec3& n, double size, const BSDF* bsdf) {
  const Vec3 ex = glm::normalize(glm::cross(Vec3(0, 1, 0), n)) * size;  // n is never along y here
  const Vec3 ey = glm::cross(n, ex);
  s.add_quad(c, ex, ey, bsdf);
}

inline MirrorChain make_mirror_chain(int mirrors) {
  MirrorChain m;
  m.mirrors = mirrors;
  Scene& s = m.scene;
  const BSDF* mirror = s.add_bsdf<NormalMirror>();
  for (int k = 1; k <= mirrors; ++k)
    add_facing_quad(s, chain_point(k), glm::normalize(chain_point(k + 1) - chain_point(k)), 0.2, mirror);
  const double albedo = 0.5, intensity = 2.0;
  const Vec3 card = chain_point(mirrors + 1);
  const Vec3 n_card = glm::normalize(chain_point(mirrors) - card);
  add_facing_quad(s, card, n_card, 0.2, s.add_bsdf<GuardedDiffuse>(Spectrum(albedo)));
  // Off the plane of the chain (y = 0.6), so that no mirror stands between it
  // and the card; in front of the card.
  const Vec3 light = card + 0.5 * n_card + Vec3(0, 0.6, 0);
  s.add_light<PointLight>(Spectrum(intensity), light);
  s.camera = Camera(chain_point(0), chain_point(1), {0, 1, 0}, 30.0, 30.0);
  s.build();
  const Vec3 to_light = light - card;
  const double d2 = glm::dot(to_light, to_light);
  m.card_radiance = albedo * kInvPi * intensity * glm::dot(n_card, to_light / std::sqrt(d2)) / d2;
  m.first = aim(s, chain_point(0), chain_point(1) - chain_point(0));
  return m;
}

}  // namespace pt::test::part4
