# Part 5 mutants: plausible student bugs in adaptive sampling (P5T1). Each one
# must make at least one graded test in tests/part5/ fail.
set(p5 reference/part5_adaptive_sampling.cpp)

# Biased variance: divides by n instead of n - 1.
pt_mutant(5 variance_over_n ${p5} [[/ (n - 1));]] [[/ n);]])

# The half-width with sqrt(n - 1): sigma^2 is already divided by n - 1.
# Caught by SampleAdaptively.HalfWidthIsSigmaOverSqrtN (hidden),
# SampleAdaptively.BatchOfOneSkipsTheFirstCheck (hidden).
pt_mutant(5 half_width_sqrt_n_minus_1 ${p5} [[1.96 * std::sqrt(var / n)]] [[1.96 * std::sqrt(var / (n - 1))]])

# Checks at n = 1 when the batch size is 1: (s2 - s1^2) / 0 = NaN, clamped
# to 0, and every pixel stops after one sample.
# Caught by SampleAdaptively.BatchOfOneSkipsTheFirstCheck (hidden),
# SampleAdaptively.HalfWidthIsSigmaOverSqrtN (hidden).
pt_mutant(5 batch_of_one_checks_first_sample ${p5} [[n % samples_per_batch == 0 && n > 1]]
          [[n % samples_per_batch == 0]])

# Forgets the square root: compares 1.96 sigma^2 / n with the tolerance.
pt_mutant(5 missing_sqrt ${p5} [[1.96 * std::sqrt(var / n)]] [[1.96 * (var / n)]])

# 1.96 sigma without the 1/sqrt(n): the spread of one sample, not of the mean.
pt_mutant(5 no_div_sqrt_n ${p5} [[std::sqrt(var / n)]] [[std::sqrt(var)]])

# Checks the rule after every sample instead of after each whole batch.
pt_mutant(5 check_every_sample ${p5} [[n % samples_per_batch == 0 && n > 1]] [[n > 1]])

# Plain average of r, g, b instead of the illuminance.
pt_mutant(5 average_rgb ${p5} [[double il = illuminance(x);]] [[double il = (x.r + x.g + x.b) / 3.0;]])

# Only the red channel.
pt_mutant(5 red_only ${p5} [[double il = illuminance(x);]] [[double il = x.r;]])

# Rec. 601 luma weights instead of the Rec. 709 illuminance.
pt_mutant(5 rec601_weights ${p5} [[double il = illuminance(x);]]
          [[double il = 0.299 * x.r + 0.587 * x.g + 0.114 * x.b;]])

# Absolute tolerance: compares the half-width with max_tolerance, without mu.
pt_mutant(5 absolute_tolerance ${p5} [[<= max_tolerance * mu)]] [[<= max_tolerance)]])

# Relative error as half-width / mu: 0/0 = NaN on a black pixel, which never stops.
pt_mutant(5 divide_by_mu ${p5} [[if (1.96 * std::sqrt(var / n) <= max_tolerance * mu) break;]]
          [[if (1.96 * std::sqrt(var / n) / mu <= max_tolerance) break;]])

# 90% instead of 95% confidence (z = 1.645).
pt_mutant(5 z_90_percent ${p5} [[if (1.96 *]] [[if (1.645 *]])

# No clamp of the variance at 0: round-off makes it slightly negative on some
# constant pixels, sqrt gives NaN and the pixel never stops.
pt_mutant(5 no_variance_clamp ${p5} [[std::max(0.0, (s2 - s1 * s1 / n) / (n - 1))]] [[(s2 - s1 * s1 / n) / (n - 1)]])

# Sums the illuminance instead of its square into s2.
pt_mutant(5 s2_not_squared ${p5} [[s2 += il * il;]] [[s2 += il;]])

# Off by one in the cap: takes max_samples + 1 samples.
pt_mutant(5 cap_off_by_one ${p5} [[while (n < max_samples)]] [[while (n <= max_samples)]])

# Returns the sum of the samples, not their mean.
pt_mutant(5 sum_not_mean ${p5} [[return {n > 0 ? sum / double(n) : Spectrum(0.0), n};]] [[return {sum, n};]])

# Divides the sum by max_samples instead of the samples actually taken.
pt_mutant(5 divide_by_max_samples ${p5} [[sum / double(n)]] [[sum / double(max_samples)]])

# Reports max_samples as the sample count.
pt_mutant(5 count_is_max_samples ${p5} [[: Spectrum(0.0), n};]] [[: Spectrum(0.0), max_samples};]])

# The pixel records ns_aa as its sample count, not the samples taken.
pt_mutant(5 pixel_count_is_ns_aa ${p5}
          [[  return sample_adaptively(next_sample, settings.ns_aa, settings.samples_per_batch, settings.max_tolerance);]]
          [[  PixelEstimate p = sample_adaptively(next_sample, settings.ns_aa, settings.samples_per_batch, settings.max_tolerance);
  p.num_samples = settings.ns_aa;
  return p;]])

# Passes the batch size as the cap and the cap as the batch size.
pt_mutant(5 swapped_cap_and_batch ${p5} [[settings.ns_aa, settings.samples_per_batch]]
          [[settings.samples_per_batch, settings.ns_aa]])

# Ignores the settings: the default batch of 32 and tolerance of 0.05.
pt_mutant(5 hardcoded_batch_and_tolerance ${p5} [[settings.samples_per_batch, settings.max_tolerance);]]
          [[32, 0.05);]])

# Pixel row counted from the top: y flipped.
pt_mutant(5 flipped_y ${p5} [[(y + u.y) / settings.height]] [[(settings.height - 1 - y + u.y) / settings.height]])

# No jitter: every sample through the pixel centre.
pt_mutant(5 no_jitter ${p5} [[Vec2 u = settings.ns_aa == 1 ? Vec2(0.5) : rng.uniform2();]] [[Vec2 u(0.5);]])

# Jitters the single sample too (ns_aa = 1 should use the pixel centre).
pt_mutant(5 jitter_single_sample ${p5} [[Vec2 u = settings.ns_aa == 1 ? Vec2(0.5) : rng.uniform2();]]
          [[Vec2 u = rng.uniform2();]])

# Divides the pixel offset by the wrong dimension (width and height swapped).
pt_mutant(5 swapped_width_height ${p5} [[(x + u.x) / settings.width, (y + u.y) / settings.height]]
          [[(x + u.x) / settings.height, (y + u.y) / settings.width]])

# Jitters with a generator of its own, seeded from the pixel.
# Caught by PixelAdaptive.UsesOnlyTheRngItIsGiven.
pt_mutant(5 own_rng ${p5} [[  auto next_sample = [&] {
    Vec2 u = settings.ns_aa == 1 ? Vec2(0.5) : rng.uniform2();]] [[  Rng own = Rng::for_pixel(0, uint32_t(x), uint32_t(y));
  auto next_sample = [&] {
    Vec2 u = settings.ns_aa == 1 ? Vec2(0.5) : own.uniform2();]])

# The Rec. 709 weights applied to the channels in B, G, R order.
# Caught by SampleAdaptively.IlluminanceWeightsFitTheirChannels (hidden).
pt_mutant(5 rec709_bgr_order ${p5} [[double il = illuminance(x);]]
          [[double il = 0.2126 * x.b + 0.7152 * x.g + 0.0722 * x.r;]])

# The weights shifted one channel along (red 0.7152, green 0.0722, blue
# 0.2126): alternating red and blue alone cannot tell (T = 6.8, stops at 8).
# Caught by SampleAdaptively.UsesRec709Illuminance (hidden),
#   SampleAdaptively.IlluminanceWeightsFitTheirChannels (hidden).
pt_mutant(5 rec709_weights_shifted ${p5} [[double il = illuminance(x);]]
          [[double il = 0.7152 * x.r + 0.0722 * x.g + 0.2126 * x.b;]])

# P5T3 (the extension: allocate_samples).
# The variance instead of its root: n proportional to r^2, the stopping
# rule's allocation. Caught by AllocateSamples.CountsFollowTheRelativeSd.
pt_mutant(5 alloc_variance_proportional ${p5} [[std::sqrt(v / (m * m + 1e-2))]] [[v / (m * m + 1e-2)]])

# sigma / mean, as if the mean could not be 0 (the epsilon left out).
pt_mutant(5 alloc_no_epsilon ${p5} [[std::sqrt(v / (m * m + 1e-2))]] [[std::sqrt(v / (m * m))]])

# sigma / max(mean, 1e-2): another offset than relMSE's.
pt_mutant(5 alloc_sigma_over_mean ${p5} [[std::sqrt(v / (m * m + 1e-2))]] [[std::sqrt(v) / std::max(m, 1e-2)]])

# NaN and infinite pilots kept. Caught by AllocateSamples.BrokenPilotsGetTheFloor.
pt_mutant(5 alloc_keeps_nan ${p5} [[std::isfinite(m) && std::isfinite(v) && v > 0]] [[v > 0]])

# No floor: noise-free pixels get no sample.
# Caught by AllocateSamples.EveryPixelGetsAtLeastOneSample.
pt_mutant(5 alloc_no_floor ${p5} [[target[i] = std::max(1.0, lambda * r[i]);]] [[target[i] = lambda * r[i];]])

# lambda = budget / sum r: the samples the floors take are spent twice.
pt_mutant(5 alloc_floors_not_paid ${p5} [[double(budget - (long long)(n - k)) / sum]] [[double(budget) / sum]])

# Each count rounded down and the rest of the budget left unspent.
pt_mutant(5 alloc_rounds_down ${p5} [[for (size_t k = 0; given < budget; k = (k + 1) % n)]]
          [[for (size_t k = 0; false; k = (k + 1) % n)]])

# A budget below the pixel count still gives every pixel one sample.
# Caught by AllocateSamples.ABudgetBelowThePixelCount.
pt_mutant(5 alloc_overspends_small_budget ${p5} [[if (budget < (long long)n) {]] [[if (false) {]])

# The quietest pixels first.
pt_mutant(5 alloc_ascending ${p5} [[return r[a] > r[b];]] [[return r[a] < r[b];]])

# The loop written as do { ... } while (n < max_samples) (here as the same
# loop with its first test skipped): one sample even with a cap of 0 or less.
# Caught by SampleAdaptively.ACapOfZeroOrLessTakesNoSample.
pt_mutant(5 cap_zero_draws_once ${p5} [[  while (n < max_samples) {]]
          [[  for (bool first = true; first || n < max_samples; first = false) {]])
