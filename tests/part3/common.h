#pragma once
// Shared set-up of the Part 3 graded tests.
//
// Significance: every graded test may fail a correct solution with
// probability below 1e-4 (the README: How you are graded). Each test spends
// kAlphaTest = 1e-5 of it, split over its m statistical checks by Šidák
// (stats::sidak_alpha(kAlphaTest, m)); the factor 10 to the budget absorbs
// the error of the large-sample approximations (CLT, chi-square law, delta
// method) that far in the tail. The checks are on means and variances of the
// estimators' output distributions, which do not depend on the order in
// which a solution draws its random numbers; nothing is compared with the
// reference implementation's own output.
//
// Power: each statistical test states the smallest relative bias that fails
// it with probability 99%, (z_{1-alpha/2} + z_0.99) x the relative standard
// error of its most precise check (measured with PT_STATS_VERBOSE=1), and,
// for a variance test, how far below its stated factor the true ratio must
// be to fail it with probability 99%, factor x exp(-(z_{1-alpha} + z_0.99) se).
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/rng.h"
#include "render/pathtracer.h"
#include "support/part3_closed_forms.h"
#include "support/part3_scenes.h"
#include "support/replayed_draws.h"
#include "support/seed.h"
#include "support/statistics.h"

namespace pt::test::part3 {

using test::parallelogram;
using test::parallelogram_irradiance;
using test::Polygon;
using test::polygon_irradiance;

constexpr double kAlphaTest = 1e-5;
constexpr double kAlbedo = 0.8;  // grey receivers: the estimate's illuminance is its value in every channel
constexpr double kL = 5.0;        // radiance of the area lights of the mean tests
constexpr int kNs = 4;            // ns_area_light of the mean tests: the 1/N averaging is exercised too

inline double alpha_each(int checks) { return stats::sidak_alpha(kAlphaTest, checks); }

// A receiver at p (normal n) in a scene, and the ray that hits it.
struct Lit {
  Scene scene;
  Vec3 p, n;
  Aim aim;
};

// Builds the scene made by `add` (lights, occluders), adds the receiver at
// (p, n) (glowing with receiver_emission, if given), builds the BVH and aims
// at the receiver.
inline Lit make_lit(const Vec3& p, const Vec3& n, const std::function<void(Scene&)>& add,
                    const Spectrum& receiver_emission = Spectrum(0.0)) {
  Lit l;
  l.p = p;
  l.n = glm::normalize(n);
  add(l.scene);
  add_receiver(l.scene, p, l.n, Spectrum(kAlbedo), receiver_emission);
  l.scene.build();
  l.aim = aim_at(l.scene, p, l.n);
  return l;
}

enum class Method { Hemisphere, Importance, OneBounce, Mis };

inline const char* name(Method m) {
  return m == Method::Hemisphere   ? "estimate_direct_lighting_hemisphere"
         : m == Method::Importance ? "estimate_direct_lighting_importance"
         : m == Method::Mis        ? "estimate_direct_lighting_mis"
                                   : "one_bounce_radiance";
}

// One estimate, as a function of the generator (support/replayed_draws.h),
// each call on a fresh copy of the ray (intersecting one shortens its max_t).
inline Spectrum estimate(const PathTracer& t, const Ray& ray, const Intersection& isect, Method m, Rng& rng) {
  return test::replayed(name(m), rng, [&](Rng& r) {
    const Ray fresh = ray;
    switch (m) {
      case Method::Hemisphere: return t.estimate_direct_lighting_hemisphere(fresh, isect, r);
      case Method::Importance: return t.estimate_direct_lighting_importance(fresh, isect, r);
      case Method::Mis: return t.estimate_direct_lighting_mis(fresh, isect, r);
      default: return t.one_bounce_radiance(fresh, isect, r);
    }
  });
}

inline Spectrum estimate(const PathTracer& t, const Aim& a, Method m, Rng& rng) {
  return estimate(t, a.ray, a.isect, m, rng);
}

// One sample of sample_f, as a function of the generator.
struct BsdfSampled {
  Spectrum f;
  Vec3 wi;
  double pdf;
};
inline BsdfSampled sample_f(const BSDF& bsdf, const Vec3& wo, Rng& rng, double pdf_before = 0.0) {
  return test::replayed("DiffuseBSDF::sample_f", rng, [&](Rng& r) {
    BsdfSampled s{Spectrum(0.0), Vec3(0.0), pdf_before};
    s.f = bsdf.sample_f(wo, &s.wi, &s.pdf, r);
    return s;
  });
}

inline RenderSettings settings_with(int ns_area_light, bool hemisphere = false) {
  RenderSettings s;
  s.ns_area_light = ns_area_light;
  s.direct_hemisphere_sample = hemisphere;
  s.max_ray_depth = 1;
  return s;
}

// n estimates (each of settings.ns_area_light samples per light) of the
// outgoing radiance at the receiver, as scalars (illuminance of a grey value).
inline stats::RunningStats run(const Lit& lit, Method m, const RenderSettings& s, int n, uint64_t seed) {
  PathTracer tracer(lit.scene, s);
  Rng rng(seed);
  stats::RunningStats st;
  for (int i = 0; i < n; ++i) st.add(illuminance(estimate(tracer, lit.aim, m, rng)));
  return st;
}

// The configuration of the variance tests: the 0.8 x 0.6 light of
// lambert_cases() at height 1, radiance 5, above a receiver facing it.
inline Lit moderate_light() {
  return make_lit({0, 0, 0}, {0, 0, 1}, [](Scene& s) { s.add_area_light(Spectrum(5.0), {0, 0, 1}, {0.8, 0, 0}, {0, -0.6, 0}); });
}

// A 0.05 x 0.05 light 192 times brighter: the same irradiance (to 2%) from
// a light of 1/192 the solid angle (0.0025 sr, 4e-4 of the hemisphere).
inline Lit small_bright_light() {
  return make_lit({0, 0, 0}, {0, 0, 1},
                  [](Scene& s) { s.add_area_light(Spectrum(5.0 * 192), {0, 0, 1}, {0.05, 0, 0}, {0, -0.05, 0}); });
}

// Radiance a ray from `from` towards `to` sees emitted by the first surface hit.
inline Spectrum seen(const Scene& s, const Vec3& from, const Vec3& to) {
  Ray r(from, glm::normalize(to - from));
  Intersection isect;
  if (!s.intersect(r, &isect)) throw std::logic_error("test set-up: the ray misses");
  PathTracer tracer(s, RenderSettings{});
  return tracer.zero_bounce_radiance(r, isect);
}

// Outgoing radiance of the Lambertian receiver under irradiance E.
inline double lambert_out(double irradiance) { return kAlbedo * kInvPi * irradiance; }

}  // namespace pt::test::part3
