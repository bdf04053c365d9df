# Part 3 mutant gallery: plausible student bugs in reference/part3_direct_lighting.cpp.
# Each must make at least one graded Part 3 test fail (the test that catches
# each one is named in handouts/part3.md, "Known failure modes").
#
# Left out on purpose: taking ns_area_light samples of a delta light too. The
# samples are all the same direction and value, so the average is identical:
# not a bias and not a variance, only wasted shadow rays (a cost that the
# benchmarks, not pass/fail tests, are for).
set(ref reference/part3_direct_lighting.cpp)

# ---- P3T1: DiffuseBSDF
pt_mutant(3 missing_inv_pi ${ref} [[return reflectance * kInvPi;]] [[return reflectance;]])
pt_mutant(3 sample_f_uniform_pdf ${ref}
  [[*pdf = pdf_cosine_hemisphere(*wi);]] [[*pdf = pdf_uniform_hemisphere(*wi);]])
pt_mutant(3 sample_f_uniform_directions ${ref}
  [[*wi = sample_cosine_hemisphere(rng.uniform2());]] [[*wi = sample_uniform_hemisphere(rng.uniform2());]])
pt_mutant(3 sample_f_returns_albedo ${ref} [[  return f(wo, *wi);]] [[  return reflectance;]])
# Directions from a generator of its own, the one passed in left alone: the
# right distribution, but not a function of the generator. Caught by the
# replays (support/replayed_draws.h in one process, the boundary's runs across
# it): "its answer is not a function of its arguments and the generator".
pt_mutant(3 sample_f_static_generator ${ref}
  [[*wi = sample_cosine_hemisphere(rng.uniform2());]]
  [[static Rng own(12345);
  *wi = sample_cosine_hemisphere(own.uniform2());]])

# ---- P3T2: zero_bounce_radiance
pt_mutant(3 zero_bounce_wrong_side ${ref}
  [[return isect.bsdf->get_emission(frame.to_local(-r.d));]] [[return isect.bsdf->get_emission(frame.to_local(r.d));]])

# ---- P3T3: uniform hemisphere sampling
pt_mutant(3 hemisphere_missing_cos ${ref}
  [[L += isect.bsdf->f(w_out, w_in) * Li * w_in.z / pdf;]] [[L += isect.bsdf->f(w_out, w_in) * Li / pdf;]])
pt_mutant(3 hemisphere_cosine_pdf ${ref}
  [[double pdf = pdf_uniform_hemisphere(w_in);]] [[double pdf = pdf_cosine_hemisphere(w_in);]])
pt_mutant(3 hemisphere_cosine_samples ${ref}
  [[Vec3 w_in = sample_uniform_hemisphere(rng.uniform2());]] [[Vec3 w_in = sample_cosine_hemisphere(rng.uniform2());]])
# Keeps the random numbers away from 0 and 1 ("to avoid singular points"):
# directions within 5 degrees of the normal (z > 0.996) and a 0.4% sliver of
# azimuth are never sampled, while the pdf still says 1 / (2 pi). The
# statistical-power mutant: about -2.4% for the receiver below the light
# (t = -7.6 to -9.1 at seed offsets 0 to 2 with 400,000 estimates; with the
# 100,000 the visible test took before, about -4, under its threshold 4.85),
# -2% to +1% elsewhere. Caught by HemisphereLighting.MatchesLambertForAreaLights,
# HemisphereLighting.SeesEmittersWhenTheLightListIsEmpty,
# HemisphereLighting.VarianceExplodesForASmallBrightLight (the 0.05 x 0.05
# light overhead lies inside the cap it never samples),
# HemisphereLighting.ShadowsOnlyWhereAnOccluderBlocks (hidden).
pt_mutant(3 hemisphere_avoids_endpoints ${ref}
  [[Vec3 w_in = sample_uniform_hemisphere(rng.uniform2());]]
  [[Vec3 w_in = sample_uniform_hemisphere(rng.uniform2() * 0.996 + Vec2(0.002));]])
pt_mutant(3 hemisphere_samples_sphere ${ref}
  [[Vec3 w_in = sample_uniform_hemisphere(rng.uniform2());]] [[Vec3 w_in = sample_uniform_sphere(rng.uniform2());]])
pt_mutant(3 hemisphere_world_space_directions ${ref} [[Vec3 wi = frame.to_world(w_in);]] [[Vec3 wi = w_in;]])
pt_mutant(3 hemisphere_counts_back_of_light ${ref}
  [[light_isect.bsdf->get_emission(Frame::from_normal(light_isect.n).to_local(-wi))]]
  [[light_isect.bsdf->get_emission(Vec3(0, 0, 1))]])
pt_mutant(3 hemisphere_no_background ${ref} [[: scene->background(wi);]] [[: Spectrum(0.0);]])
pt_mutant(3 hemisphere_no_epsilon ${ref}
  [[    shadow.min_t = kRayEpsilon;
    Intersection light_isect;]]
  [[    Intersection light_isect;]])
pt_mutant(3 hemisphere_not_divided_by_n ${ref} [[return L / double(n);]] [[return L;]])
# N = ns_area_light: the number of lights ignored (the same as the reference
# with one light, only noisier with several). Caught by
# HemisphereLighting.SampleCountGrowsWithTheLights (hidden).
pt_mutant(3 hemisphere_ignores_light_count ${ref}
  [[const int n = std::max<int>(1, int(scene->lights.size()) * settings.ns_area_light);]]
  [[const int n = std::max(1, settings.ns_area_light);]])
# N = lights x ns_area_light with no floor: no sample and 0 / 0 with an empty
# light list. Caught by HemisphereLighting.SeesEmittersWhenTheLightListIsEmpty.
pt_mutant(3 hemisphere_no_sample_without_lights ${ref}
  [[const int n = std::max<int>(1, int(scene->lights.size()) * settings.ns_area_light);]]
  [[const int n = int(scene->lights.size()) * settings.ns_area_light;]])
pt_mutant(3 hemisphere_one_sample ${ref}
  [[const int n = std::max<int>(1, int(scene->lights.size()) * settings.ns_area_light);]] [[const int n = 1;]])

# ---- P3T4: light sampling
pt_mutant(3 importance_missing_cos ${ref}
  [[L_light += isect.bsdf->f(w_out, w_in) * Li * w_in.z / pdf;]] [[L_light += isect.bsdf->f(w_out, w_in) * Li / pdf;]])
pt_mutant(3 importance_pdf_twice ${ref}
  [[L_light += isect.bsdf->f(w_out, w_in) * Li * w_in.z / pdf;]]
  [[L_light += isect.bsdf->f(w_out, w_in) * Li * w_in.z / pdf / pdf;]])
pt_mutant(3 importance_world_space_wi ${ref} [[Vec3 w_in = frame.to_local(wi);]] [[Vec3 w_in = wi;]])
pt_mutant(3 importance_no_horizon_check ${ref}
  [[if (pdf <= 0.0 || w_in.z <= 0.0) continue;]] [[if (pdf <= 0.0) continue;]])
pt_mutant(3 importance_no_pdf_check ${ref}
  [[if (pdf <= 0.0 || w_in.z <= 0.0) continue;]] [[if (w_in.z <= 0.0) continue;]])
pt_mutant(3 shadow_ray_unbounded ${ref} [[Ray shadow(hit_p, wi, dist - kRayEpsilon);]] [[Ray shadow(hit_p, wi);]])
pt_mutant(3 shadow_ray_reaches_light ${ref}
  [[Ray shadow(hit_p, wi, dist - kRayEpsilon);]] [[Ray shadow(hit_p, wi, dist);]])
pt_mutant(3 importance_no_epsilon ${ref}
  [[      shadow.min_t = kRayEpsilon;
      if (scene->has_intersection(shadow)) continue;]]
  [[      if (scene->has_intersection(shadow)) continue;]])
pt_mutant(3 average_over_all_lights ${ref}
  [[L += L_light / double(n);]] [[L += L_light / double(n * scene->lights.size());]])
pt_mutant(3 importance_sum_not_average ${ref} [[L += L_light / double(n);]] [[L += L_light;]])
pt_mutant(3 importance_one_sample ${ref}
  [[const int n = light->is_delta_light() ? 1 : settings.ns_area_light;]] [[const int n = 1;]])
# One sample whatever ns_area_light, returned as the mean of the last
# ns_area_light such estimates for the same ray: each answer's variance falls
# as 1/N, as the variance tests ask, from a cache across calls. Caught by the
# replays: the same call again is a mean of other samples.
pt_mutant(3 importance_averages_last_estimates ${ref}
  [[    L += L_light / double(n);
  }
  return L;]]
  [[    L += L_light;
  }
  struct Cached {
    Vec3 o, d;
    int ns;
    std::vector<Spectrum> raw;
  };
  static std::vector<Cached> cache;
  Cached* c = nullptr;
  for (Cached& e : cache)
    if (e.o == r.o && e.d == r.d && e.ns == settings.ns_area_light) c = &e;
  if (!c) {
    if (cache.size() > 64) cache.clear();
    cache.push_back({r.o, r.d, settings.ns_area_light, {}});
    c = &cache.back();
  }
  c->raw.push_back(L);
  if (c->raw.size() > size_t(std::max(1, settings.ns_area_light))) c->raw.erase(c->raw.begin());
  Spectrum mean(0.0);
  for (const Spectrum& x : c->raw) mean += x;
  return mean / double(c->raw.size());]])

# ---- P3T5: one_bounce_radiance
pt_mutant(3 one_bounce_swapped ${ref}
  [[return settings.direct_hemisphere_sample ?]] [[return !settings.direct_hemisphere_sample ?]])
# The surface's own emission added to its direct light: every emitter seen by
# the camera twice as bright, and counted again at every vertex of a path.
# Caught by OneBounce.LeavesOutTheSurfacesOwnEmission.
pt_mutant(3 one_bounce_adds_emission ${ref}
  [[  return settings.direct_hemisphere_sample ? estimate_direct_lighting_hemisphere(r, isect, rng)
                                           : estimate_direct_lighting_importance(r, isect, rng);]]
  [[  return zero_bounce_radiance(r, isect) + (settings.direct_hemisphere_sample
                                                 ? estimate_direct_lighting_hemisphere(r, isect, rng)
                                                 : estimate_direct_lighting_importance(r, isect, rng));]])
# The sample count decided once, by the first light: with a delta light first,
# every area light and the sky get one sample (unbiased; their noise does not
# fall with ns_area_light). Caught by
# LightSampling.EveryLightWithAnAreaTakesNsAreaLightSamples.
pt_mutant(3 count_of_the_first_light ${ref}
  [[  for (const auto& light : scene->lights) {
    // A delta light has a single direction: more samples would repeat it.
    const int n = light->is_delta_light() ? 1 : settings.ns_area_light;]]
  [[  const int n = !scene->lights.empty() && scene->lights[0]->is_delta_light() ? 1 : settings.ns_area_light;
  for (const auto& light : scene->lights) {]])

# ---- Randomness only from the Rng passed in (each caught by DirectRandomness.*)
# sample_f drawing from a static generator of its own: right distribution,
# renders no longer reproducible per pixel, threads racing on one generator.
pt_mutant(3 sample_f_own_generator ${ref}
  [[*wi = sample_cosine_hemisphere(rng.uniform2());]]
  [[static Rng own(12345);
  *wi = sample_cosine_hemisphere(own.uniform2());]])
pt_mutant(3 hemisphere_own_generator ${ref}
  [[Vec3 w_in = sample_uniform_hemisphere(rng.uniform2());]]
  [[static Rng own(12345);
    Vec3 w_in = sample_uniform_hemisphere(own.uniform2());]])
# Light sampling from a copy: the rng passed in never moves, so the next
# estimate (Part 4's next vertex) draws the very same numbers again.
pt_mutant(3 importance_copies_rng ${ref}
  [[Spectrum PathTracer::estimate_direct_lighting_importance(const Ray& r, const Intersection& isect, Rng& rng) const {]]
  [[Spectrum PathTracer::estimate_direct_lighting_importance(const Ray& r, const Intersection& isect, Rng& rng_in) const {
  Rng rng = rng_in;]])
pt_mutant(3 one_bounce_copies_rng ${ref}
  [[Spectrum PathTracer::one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const {]]
  [[Spectrum PathTracer::one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng_in) const {
  Rng rng = rng_in;]])

# ---- P3T6, the extension: multiple importance sampling (test_mis.cpp)
# BSDF samples added with weight 1 beside weighted light samples: the weights
# of a direction no longer sum to one (the light counted up to twice). Caught
# by MisLighting.MatchesLambertForAreaLights.
pt_mutant(3 mis_bsdf_samples_unweighted ${ref}
  [[L += f * Li * local.z / bsdf_pdf * (bsdf_pdf / densities(dir, local)) / double(m);]]
  [[L += f * Li * local.z / bsdf_pdf / double(m);]])
# A wrong pdf in one strategy's weight: the light samples weighed against the
# uniform hemisphere's density, the BSDF samples against the cosine one that
# drew them; the two weights of a direction no longer sum to one. Caught by
# MisLighting.MatchesLambertForAreaLights.
pt_mutant(3 mis_light_weight_uniform_pdf ${ref}
  [[const double weight = delta ? 1.0 : light_pdf / densities(dir, local);]]
  [[const double weight = delta ? 1.0 : light_pdf / (light_pdf + pdf_uniform_hemisphere(local));]])
# A light sample blocked by an emitter counted as dark, where a BSDF sample in
# the same direction sees the emitter: the two strategies estimate different
# things (the sky's samples hidden by the area lights). Caught by
# MisLighting.SumsOverLightsAndSeesEmittersThatAreNoLights.
pt_mutant(3 mis_light_sample_shadowed_by_emitters ${ref}
  [[Li = arriving(dir, dist - kRayEpsilon, Le);]]
  [[Li = arriving(dir, dist - kRayEpsilon, Le) == Le ? Le : Spectrum(0.0);]])
# Light sampling alone, unweighted (P3T4's estimator): unbiased, and its
# variance under a large light just above the surface thousands of times the
# bound. Caught by MisLighting.NoWorseThanBsdfSamplingForALargeDimLight.
pt_mutant(3 mis_light_sampling_alone ${ref}
  [[      const double weight = delta ? 1.0 : light_pdf / densities(dir, local);
      L += isect.bsdf->f(wo, local) * Li * local.z / light_pdf * weight / double(n);
    }
  }
  for (int i = 0; i < m; ++i) {]]
  [[      const double weight = 1.0;
      L += isect.bsdf->f(wo, local) * Li * local.z / light_pdf * weight / double(n);
    }
  }
  for (int i = 0; i < 0; ++i) {]])
# BSDF sampling alone, unweighted, the delta lights kept: unbiased, and its
# variance under a small bright light thousands of times the bound. Caught by
# MisLighting.NoWorseThanLightSamplingForASmallBrightLight.
pt_mutant(3 mis_bsdf_sampling_alone ${ref}
  [[      const double weight = delta ? 1.0 : light_pdf / densities(dir, local);
      L += isect.bsdf->f(wo, local) * Li * local.z / light_pdf * weight / double(n);
    }
  }
  for (int i = 0; i < m; ++i) {
    Vec3 local;
    double bsdf_pdf;
    const Spectrum f = isect.bsdf->sample_f(wo, &local, &bsdf_pdf, rng);
    if (bsdf_pdf <= 0.0 || local.z <= 0.0) continue;
    const Vec3 dir = frame.to_world(local);
    const Spectrum Li = arriving(dir, kInf, scene->background(dir));
    L += f * Li * local.z / bsdf_pdf * (bsdf_pdf / densities(dir, local)) / double(m);]]
  [[      const double weight = delta ? 1.0 : 0.0;
      L += isect.bsdf->f(wo, local) * Li * local.z / light_pdf * weight / double(n);
    }
  }
  for (int i = 0; i < m; ++i) {
    Vec3 local;
    double bsdf_pdf;
    const Spectrum f = isect.bsdf->sample_f(wo, &local, &bsdf_pdf, rng);
    if (bsdf_pdf <= 0.0 || local.z <= 0.0) continue;
    const Vec3 dir = frame.to_world(local);
    const Spectrum Li = arriving(dir, kInf, scene->background(dir));
    L += f * Li * local.z / bsdf_pdf / double(m);]])
