#pragma once
// Budgeted adaptive sampling (--adaptive-budget SPP, handouts/part5.md
// section 9, "How far from the best allocation"): framework code, not a student task.
//
// For a fixed total of samples, the expected relMSE sum_p v_p / n_p (v_p the
// relative variance of one sample of pixel p) is smallest with n_p ∝ r_p =
// sqrt(v_p) (Lagrange). The renderer estimates r_p from a pilot pass and
// spends the rest of the budget in proportion to it.
//
// Unbiased by construction: a pixel's count is computed from its neighbours'
// pilot samples only, never from its own, and every pixel's pilot has the
// same size. The count is therefore independent of the pixel's own samples
// (each pixel draws from streams of its own), and the mean of all its samples,
// pilot included, is unbiased given the count. (A count that depended on the
// pixel's own values, as the stopping rule's does, would weigh lucky and
// unlucky samples unequally: a pilot that happened to be noisy earns more
// samples, which dilute it.) The price of leaving the pixel out: a noisy
// feature is seen only through its neighbours, so its samples spread over the
// pixels around it.
//
// Rounds (--adaptive-rounds K > 1) re-estimate r before each round from every
// sample taken so far, which lowers the pilot's noise. They give up the
// exact independence above: a neighbour's later samples are as many as this
// pixel's earlier values made them, so those values reach the pixel's count
// at second order (through how precisely its neighbours' variances are
// known, never through their expected value). pt-study's allocation
// experiment measures both the gain and the bias (handouts/part5.md, section 9).
#include <vector>

#include "render/renderer.h"

namespace pt {

// Pilot samples per pixel for a mean budget of `budget` samples per pixel:
// an eighth of it, at least 2 (a variance needs two) and at most 8 (16
// samples on each line of two neighbours, 64 around the pixel). The pilot is
// averaged too.
int pilot_samples(int budget);

// Running sums of one pixel's samples, per channel.
struct PixelSums {
  Spectrum sum{0.0}, sum_sq{0.0};
  int n = 0;
  bool finite = true;  // false when a sample was NaN or infinite
};

// r_p, pooled from p's neighbours, p itself left out (see above): for each
// of the four lines through p (horizontal, vertical, two diagonals), the
// mean over channels of the two neighbours' summed sample variances over
// their summed squared means + eps (relMSE's 1e-2), and r_p^2 the largest of
// the four. A noisy edge one pixel wide lies along one of them, so its pixels
// still see it in full (averaged over all eight neighbours, it would be a
// quarter of it), and the pixels beside it see half. Pixels without two
// finite samples are left out; r_p = 0 where no line has any.
std::vector<double> pooled_relative_sd(const std::vector<PixelSums>& pilot, int width, int height);

// The same rule on known moments (pt-study feeds it the true variances to
// measure what the pilot's noise costs): per pixel, the mean and per-sample
// variance of each channel, and whether to pool it at all.
struct PixelMoments {
  Spectrum mean{0.0}, var{0.0};
  bool usable = false;
};
std::vector<double> pooled_relative_sd(const std::vector<PixelMoments>& pixels, int width, int height);

// Integer counts, one per pixel, summing exactly to `total`: n_p = clamp(lambda
// r_p, floor, cap) with lambda chosen to spend `total` (water-filling), rounded
// down and the remainder given one each to the largest fractional parts (ties
// to the lower index). When every r_p is 0 (or not finite) the total is shared
// equally. Requires floor * size <= total <= cap * size.
std::vector<int> allocate_counts(const std::vector<double>& r, long long total, int floor, int cap);
// The same with a floor per pixel (a round's counts so far): n_p =
// clamp(lambda r_p, floors_p, cap), what is left over the floors shared
// equally when every r_p is 0. Requires sum floors <= total <= cap * size.
std::vector<int> allocate_counts(const std::vector<double>& r, long long total, const std::vector<int>& floors,
                                 int cap);

// The render: a pilot of pilot_samples(B) per pixel (stream pass 1), then K
// rounds (settings.adaptive_rounds), each spending an equal share of the rest
// of B x pixels: counts from allocate_counts on r pooled from every sample so
// far, with the counts so far as floors, and each pixel's new samples (stream
// pass 2 + round). A pixel's value is the mean of all its samples.
// Deterministic with the seed on any number of threads.
RenderResult render_budgeted(const PathTracer& tracer, int threads, const ProgressFn& progress);

}  // namespace pt
