#pragma once
// Checks that more than one direct-lighting estimator is held to: the means
// of lambert_cases() against Lambert's formula, and the exact answer for
// delta lights. One test per estimator calls them (test_direct_lighting.cpp,
// test_mis.cpp).
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "common.h"

namespace pt::test::part3 {

// What the pooled test's failure may claim: the ratios mean/expected it
// pooled, and a constant factor only when they agree (within 5% of each
// other, far beyond their standard errors of at most 2%).
inline std::string factor_hint(const std::vector<stats::MeanAgainst>& pool) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& c : pool) {
    if (c.expected == 0) continue;
    const double ratio = c.sample->mean() / c.expected;
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  std::ostringstream os;
  os << std::setprecision(3) << "mean / expected ranges from " << lo << " to " << hi << " over the configurations";
  if (lo > 0 && hi / lo < 1.05)
    os << ": off by about the same factor in every one: look for a constant (1/pi, 2 pi, the 1/N of the average)";
  else
    os << ": not one common factor; compare the configurations that fail above (distance, angles, the light's "
          "pdf)";
  return os.str();
}

// Configurations of lambert_cases(): the light 0.8 x 0.6 at height 1 (or the
// tilted one), points below, beside, partly or wholly below the horizon,
// behind the light. One t test per configuration and one pooled test of a
// relative bias common to all of them (statistics.h), alpha split 9 ways.
inline void check_lambert_cases(Method m, int n, uint64_t seed) {
  const auto cases = lambert_cases();
  const double alpha = alpha_each(int(cases.size()) + 1);
  std::vector<stats::RunningStats> samples(cases.size());
  std::vector<stats::MeanAgainst> pool;
  for (size_t k = 0; k < cases.size(); ++k) {
    const LambertCase& c = cases[k];
    Lit lit = make_lit(c.p, c.n, [&](Scene& s) { s.add_area_light(Spectrum(kL), c.c, c.ex, c.ey); });
    const double expected = lambert_out(parallelogram_irradiance(c.p, c.n, c.c, c.ex, c.ey, kL));
    samples[k] = run(lit, m, settings_with(kNs), n, test::seed(seed++));
    pool.push_back({&samples[k], expected});
    EXPECT_TRUE(stats::mean_matches(samples[k], expected, alpha, std::string(name(m)) + ", " + c.name))
        << std::setprecision(6) << "albedo " << kAlbedo << ", light radiance " << kL << ", closed form: (albedo/pi) * Lambert's irradiance";
  }
  EXPECT_TRUE(stats::check(stats::pooled_relative_bias(pool, alpha, std::string(name(m)) + ", all receivers")))
      << factor_hint(pool);
}

// A point light of intensity I at distance d, at angle theta from the
// normal: L_out = (albedo/pi) I cos(theta) / d^2, exactly (one sample, no
// randomness). Directional light of radiance Ld from angle theta:
// (albedo/pi) Ld cos(theta). Behind the receiver: 0. A wall just behind
// the point light (a shadow ray that does not stop at the light hits it), a
// black quad beside the path (no false shadow), and one across it (shadow).
// Exact to 1e-9 relative: no statistics, any deviation fails.
inline void check_delta_lights(Method m, uint64_t seed) {
  const double I = 3.0, Ld = 2.0;
  const Vec3 n = glm::normalize(Vec3(0.2, -0.1, 1));
  const RenderSettings settings = settings_with(8);  // ns_area_light is for area lights only
  struct Case {
    const char* name;
    Vec3 light;  // point light position, or the direction a directional light travels
    bool point, occluded;
  };
  const std::vector<Case> cases = {
      {"point light overhead", {0.3, 0.2, 1.5}, true, false},
      {"point light at a grazing angle", {2.0, -1.0, 0.25}, true, false},
      {"point light below the horizon", {1.0, 0.0, -0.5}, true, false},
      {"point light behind an occluder", {-0.5, -0.5, 1.2}, true, true},
      {"directional light", {-0.3, 0.4, -1.0}, false, false},
      {"directional light at a grazing angle", {-1.0, 0.2, -0.12}, false, false},
      {"directional light from below", {0.0, 0.3, 1.0}, false, false},
      {"directional light behind an occluder", {0.5, 0.5, -1.0}, false, true},
  };
  for (const Case& c : cases) {
    const Vec3 wi = c.point ? glm::normalize(c.light) : -glm::normalize(c.light);
    Lit lit = make_lit({0, 0, 0}, n, [&](Scene& s) {
      const BSDF* black = s.add_bsdf<DiffuseBSDF>(Spectrum(0.0));
      if (c.point) {
        s.add_light<PointLight>(Spectrum(I), c.light);
        // A wall facing the receiver 0.3 beyond the light.
        const Vec3 a = glm::normalize(glm::cross(wi, Vec3(0.3, 0.7, 0.1)));
        s.add_quad(c.light + 0.3 * wi, 2.0 * a, 2.0 * glm::cross(wi, a), black);
      } else {
        s.add_light<DirectionalLight>(Spectrum(Ld), c.light);
      }
      // A quad across the line of the path, its edge 0.05 to the side of it.
      const Vec3 side = glm::normalize(glm::cross(wi, Vec3(0.1, 0.9, 0.3)));
      const Vec3 up = glm::cross(wi, side);
      const Vec3 mid = 0.5 * (c.point ? glm::length(c.light) : 2.0) * wi;
      s.add_quad(mid + 0.35 * side, side * 0.6, up * 0.6, black);
      if (c.occluded) s.add_quad(0.5 * wi, side * 0.3, up * 0.3, black);  // across the path itself
    });
    double expected = 0.0;
    const double cos_theta = glm::dot(n, wi);
    if (!c.occluded && cos_theta > 0.0)
      expected = lambert_out(c.point ? I * cos_theta / glm::dot(c.light, c.light) : Ld * cos_theta);
    PathTracer tracer(lit.scene, settings);
    Rng rng(test::seed(seed));
    for (int k = 0; k < 3; ++k) {  // deterministic: the same every time
      const Spectrum L = estimate(tracer, lit.aim, m, rng);
      for (int ch = 0; ch < 3; ++ch) {
        const double rel = expected > 0.0 ? std::abs(L[ch] - expected) / expected : 0.0;
        EXPECT_NEAR(L[ch], expected, 1e-9 * expected + 1e-15)
            << c.name << ", channel " << ch
            << (rel > 1e-9 && rel < 1e-2
                    ? " (off by a relative " + std::to_string(rel) +
                          ": sample the light from the hit point itself, r.at(isect.t), and use that point and "
                          "the distance sample_L returns as they are; only the shadow ray's min_t = kRayEpsilon "
                          "offsets anything, never the point or the light's distance)"
                    : std::string());
      }
    }
  }
}

}  // namespace pt::test::part3
