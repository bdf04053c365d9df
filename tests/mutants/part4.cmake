# Part 4 mutant gallery: plausible student bugs in reference/part4_global_illumination.cpp.
# Each must make at least one graded Part 4 test fail; the tests that catch
# each one are listed in handouts/part4.md, "How it is graded".
set(ref reference/part4_global_illumination.cpp)

# ---- P4T1: the recursion -------------------------------------------------------
# Bounce weight f / pdf without the cosine (mean 2a instead of a in the furnace).
pt_mutant(4 missing_cos ${ref} [[* (w_in.z / (pdf * p));]] [[* (1.0 / (pdf * p));]])
# Dividing by the pdf twice.
pt_mutant(4 pdf_twice ${ref} [[* (w_in.z / (pdf * p));]] [[* (w_in.z / (pdf * pdf * p));]])
# Emission added at every vertex (zero_bounce_radiance of each hit, not only the camera's).
pt_mutant(4 emission_every_bounce ${ref} [[  Spectrum L(0.0);]] [[  Spectrum L = zero_bounce_radiance(r, isect);]])
# Depth off by one, two ways: two bounces used per level, or one level too many.
pt_mutant(4 depth_minus_two ${ref}
  [[Ray bounce(r.at(isect.t), wi, kInf, r.depth - 1);]] [[Ray bounce(r.at(isect.t), wi, kInf, r.depth - 2);]])
pt_mutant(4 depth_stops_at_zero ${ref} [[if (r.depth <= 1) return L;]] [[if (r.depth <= 0) return L;]])
# Depth not decremented: every bounce ray gets max_ray_depth - 1, so below the
# first bounce the depth never runs out and only Russian roulette (or a ray
# leaving the scene) ends the path; with p = 1 the tests' path guard stops it.
pt_mutant(4 depth_not_decremented ${ref}
  [[Ray bounce(r.at(isect.t), wi, kInf, r.depth - 1);]]
  [[Ray bounce(r.at(isect.t), wi, kInf, settings.max_ray_depth - 1);]])
# A bounce ray that escapes adds the sky again (already counted as direct light).
pt_mutant(4 background_at_escaping_bounce ${ref}
  [[if (!scene->intersect(bounce, &next)) return L;]]
  [[if (!scene->intersect(bounce, &next)) return L + f * scene->background(wi) * (w_in.z / (pdf * p));]])
# Bounce isolation keeping the first bounce instead of the last.
pt_mutant(4 isolation_keeps_first_bounce ${ref}
  [[if (settings.accumulate_bounces || r.depth == 1) L +=]]
  [[if (settings.accumulate_bounces || r.depth == settings.max_ray_depth) L +=]])
# accumulate_bounces ignored at the vertices: every bounce up to m is kept.
pt_mutant(4 accumulate_ignored ${ref} [[if (settings.accumulate_bounces || r.depth == 1) L +=]] [[L +=]])

# ---- P4T2: Russian roulette ----------------------------------------------------------
# Survivors not divided by p: biased low.
pt_mutant(4 rr_not_divided_by_p ${ref} [[* (w_in.z / (pdf * p));]] [[* (w_in.z / pdf);]])
# Roulette on the first bounce too.
pt_mutant(4 rr_on_first_bounce ${ref}
  [[const bool first_bounce = r.depth == settings.max_ray_depth;]] [[const bool first_bounce = false;]])
# Continuing with probability 1 - p instead of p (still divided by p).
pt_mutant(4 rr_inverted ${ref} [[if (!first_bounce && !rng.coin_flip(p)) return L;]]
  [[if (!first_bounce && rng.coin_flip(p)) return L;]])
# No roulette at all: unbiased, but the variance does not rise (and deep paths are slow).
pt_mutant(4 no_russian_roulette ${ref}
  [[const double p = first_bounce ? 1.0 : settings.rr_continue_prob;
  if (!first_bounce && !rng.coin_flip(p)) return L;]]
  [[const double p = 1.0;]])

# ---- P4T3: est_radiance_global_illumination ------------------------------------------
# Zero-bounce radiance (and the sky seen directly) kept in every bounce image.
pt_mutant(4 zero_bounce_always_kept ${ref}
  [[const bool keep_zero = settings.accumulate_bounces || settings.max_ray_depth == 0;]]
  [[const bool keep_zero = true;]])
# Bounce 0 alone (max_ray_depth 0, accumulate off) comes out black.
pt_mutant(4 zero_bounce_dropped_when_isolated ${ref}
  [[const bool keep_zero = settings.accumulate_bounces || settings.max_ray_depth == 0;]]
  [[const bool keep_zero = settings.accumulate_bounces;]])
# max_ray_depth = 1 treated as "no bounce": only emission.
pt_mutant(4 depth_one_skipped ${ref} [[if (settings.max_ray_depth >= 1) {]] [[if (settings.max_ray_depth > 1) {]])
# The first hit's ray starts with one bounce too many.
pt_mutant(4 first_depth_plus_one ${ref}
  [[ray.depth = settings.max_ray_depth;]] [[ray.depth = settings.max_ray_depth + 1;]])
# Roulette one bounce late: the first two bounces exempt (unbiased, less
# variance than the contract's). Caught by RussianRoulette.DecidesFromTheSecondBounceOn.
pt_mutant(4 rr_from_the_third_bounce ${ref}
  [[const bool first_bounce = r.depth == settings.max_ray_depth;]]
  [[const bool first_bounce = r.depth >= settings.max_ray_depth - 1;]])

# ---- Randomness only from the Rng passed in (each caught by PathRandomness.*) --------
# Bounce directions from a static generator of the task's own.
pt_mutant(4 bounce_own_generator ${ref}
  [[Spectrum f = isect.bsdf->sample_f(frame.to_local(-r.d), &w_in, &pdf, rng);]]
  [[static Rng own(12345);
  Spectrum f = isect.bsdf->sample_f(frame.to_local(-r.d), &w_in, &pdf, own);]])
# The roulette coin drawn with std::rand(): the rng passed in never sees it.
pt_mutant(4 rr_coin_std_rand ${ref}
  [[if (!first_bounce && !rng.coin_flip(p)) return L;]]
  [[if (!first_bounce && !(std::rand() < p * RAND_MAX)) return L;]])
# The camera ray's path traced with a copy of the generator: the rng passed in
# never moves, so the pixel's next sample repeats this one's numbers.
pt_mutant(4 global_copies_rng ${ref}
  [[L += at_least_one_bounce_radiance(ray, isect, rng);]]
  [[Rng copy = rng;
    L += at_least_one_bounce_radiance(ray, isect, copy);]])
