#pragma once
// Shared set-up of the Part 4 graded tests.
//
// Significance: every graded test may fail a correct solution with
// probability below 1e-4 (the README: How you are graded). Each test spends
// kAlphaTest = 1e-5 of it, split over its m statistical checks by Šidák
// (stats::sidak_alpha(kAlphaTest, m)); the factor 10 to the budget absorbs the
// error of the large-sample approximations (central limit theorem, delta
// method) that far in the tail. Every check is on the mean or the variance of
// an estimator's output distribution, which does not depend on the order in
// which a solution draws its random numbers; the expected values are closed
// forms (the white furnace), exact values (the mirror chain, the sky), or an
// estimate computed once by an independent method (the Cornell box). Nothing
// is compared with the reference implementation's own output.
//
// The estimators of these tests have bounded or exponentially-tailed outputs
// (their configurations are chosen for it, see each test), so that the t test
// is valid: the furnace with hemisphere sampling (each vertex's direct light
// lies in [0, 2 a Le]) and a continuation probability p >= a, or a small
// depth, so that the path weight a^k / p^(k-1) stays bounded.
//
// Power: each statistical test states the smallest relative bias that fails
// it with probability 99%, (z_{1-alpha/2} + z_0.99) x the relative standard
// error of its checks (measured with PT_STATS_VERBOSE=1), and for a variance
// test how far below its factor the true ratio must be to fail it with
// probability 99%, factor x exp(-(z_{1-alpha} + z_0.99) se).
//
// Depth convention (handouts/part4.md): settings.max_ray_depth = m keeps
// light that bounced up to m times (m = 0: emission seen directly, m = 1:
// plus direct lighting, ...), and with accumulate_bounces off only bounce m.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include "core/rng.h"
#include "render/pathtracer.h"
#include "support/part4_scenes.h"
#include "support/replayed_draws.h"
#include "support/seed.h"
#include "support/statistics.h"

namespace pt::test::part4 {

constexpr double kAlphaTest = 1e-5;
constexpr double kLe = 1.5;  // furnace wall radiance

inline double alpha_each(int checks) { return stats::sidak_alpha(kAlphaTest, checks); }

// Le * (a^k0 + ... + a^k1): the furnace radiance of bounces k0..k1.
inline double furnace_bounces(double a, int k0, int k1, double Le = kLe) {
  double sum = 0.0;
  for (int k = k0; k <= k1; ++k) sum += std::pow(a, k);
  return Le * sum;
}

// The settings the Part 4 tests vary. Each one is set here, defaults
// included, so that a test's expected values do not move with the defaults.
inline RenderSettings gi_settings(int max_depth, double rr_continue_prob, bool accumulate = true,
                                  bool hemisphere = false) {
  RenderSettings s;
  s.max_ray_depth = max_depth;
  s.rr_continue_prob = rr_continue_prob;
  s.accumulate_bounces = accumulate;
  s.direct_hemisphere_sample = hemisphere;
  s.ns_area_light = 1;
  return s;
}

// Settings of the furnace tests: hemisphere sampling for direct light (the
// walls are not in the light list, see make_white_furnace), one sample.
inline RenderSettings furnace_settings(int max_depth, double rr_continue_prob, bool accumulate = true) {
  return gi_settings(max_depth, rr_continue_prob, accumulate, true);
}

inline std::string describe(const RenderSettings& s) {
  std::ostringstream os;
  os << "max_ray_depth=" << s.max_ray_depth << " accumulate_bounces=" << (s.accumulate_bounces ? "true" : "false")
     << " rr_continue_prob=" << s.rr_continue_prob;
  return os.str();
}

// The estimate a test takes: a scalar per call (illuminance: the value itself
// for the grey scenes of these tests).
enum class Entry {
  AtLeastOneBounce,  // at_least_one_bounce_radiance(ray with depth = max_ray_depth, first hit): P4T1, P4T2
  GlobalIllumination,  // est_radiance_global_illumination(camera ray): P4T3
};

inline const char* name(Entry e);

// One estimate, as a function of the generator (support/replayed_draws.h): a
// replayed call gets a path guard of its own too, and a fresh copy of the ray
// (intersecting a ray shortens its max_t, which is mutable).
inline Spectrum estimate_once(const PathTracer& t, const Aim& a, Entry e, Rng& rng) {
  return test::replayed(name(e), rng, [&](Rng& r) {
    path_guard().reset(guard_limit(t.settings.max_ray_depth, t.settings.rr_continue_prob),
                       guard_reason(t.settings.max_ray_depth, t.settings.rr_continue_prob));
    Ray ray = a.ray;
    if (e == Entry::GlobalIllumination) return t.est_radiance_global_illumination(ray, r);
    ray.depth = t.settings.max_ray_depth;  // the bounces still allowed at the first hit
    return t.at_least_one_bounce_radiance(ray, a.isect, r);
  });
}

// n estimates with one generator seeded by `seed`.
inline stats::RunningStats sample(const Scene& scene, const Aim& a, const RenderSettings& s, Entry e, int n,
                                  uint64_t seed) {
  PathTracer tracer(scene, s);
  Rng rng(seed);
  stats::RunningStats st;
  for (int i = 0; i < n; ++i) st.add(illuminance(estimate_once(tracer, a, e, rng)));
  return st;
}

inline const char* name(Entry e) {
  return e == Entry::GlobalIllumination ? "est_radiance_global_illumination" : "at_least_one_bounce_radiance";
}

}  // namespace pt::test::part4
