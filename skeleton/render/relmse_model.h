#pragma once
// How far a correct n-spp render may lie from a stored reference image: the
// error model shared by the library test, the grader's report and pt-study.
//
// relMSE (render/image.h, compare_images) of a test image T against the
// reference R, over P pixels and 3 channels with eps = 1e-2:
//
//   S = 1/(3P) sum_{p,c} w_pc (T_pc - R_pc)^2,    w_pc = 1 / (R_pc^2 + eps).
//
// Model. The samples of a pixel are independent and identically distributed
// (jittered in the pixel, each from the pixel's own random stream), with
// per-sample mean mu_p (a 3-vector), covariance s_p (3 x 3) and joint fourth
// cumulants k_p(c, c, c', c'). T averages n of them, R averages N others
// (independent seeds). With e = T - R:
//
//   E[S]   = 1/(3P) sum w_pc s_p(c, c) (1/n + 1/N)       = a (1/n + 1/N)
//   Var[S] = 1/(3P)^2 sum_p Var(sum_c w_pc e_pc^2)
//          = c2 (1/n + 1/N)^2 + c3 / n^3                   (to first order in n/N)
//   a  = 1/(3P)   sum_{p,c}    w_pc s_p(c,c)               relative variance of one sample
//   c2 = 2/(3P)^2 sum_{p,c,c'} w_pc w_pc' s_p(c,c')^2      the Gaussian part
//   c3 = 1/(3P)^2 sum_{p,c,c'} w_pc w_pc' k_p(c,c,c',c')   the heavy tails (fireflies)
//
// The variance follows from the moments of a mean of n i.i.d. vectors x_i:
// Cov(xbar_c^2, xbar_c'^2) = 2 s(c,c')^2 / n^2 + k(c,c,c',c') / n^3 (the
// fourth cumulant of a mean of n falls as 1/n^3, the product of covariances as
// 1/n^2). The reference's own noise enters as the 1/N in each bracket: T - R
// has covariance s (1/n + 1/N), and the stored R's error, fixed once
// rendered, adds a (1/N) to E[S] on average over the image. So at n spp the
// reference contributes a fraction n / (n + N) of the expected relMSE.
//
// The weights use the stored R (as compare_images does); S sums 3P terms, so by
// the central limit theorem it is close to normal with the mean and variance
// above, and bound(n, z) = E[S] + z sd[S] is a one-sided test of "T is a
// correct n-spp render of the scene". How close to normal it is, and whether
// the measured a, c2, c3 predict S, is checked when the reference is made
// (pt-reference-images renders independent groups of passes and records the
// observed mean and spread of S beside the model's, in the sidecar).
namespace pt::error_model {

constexpr double kRelMSEEpsilon = 1e-2;  // compare_images' offset in the denominator

struct RelMSEModel {
  double a = 0.0, c2 = 0.0, c3 = 0.0;
  int reference_samples = 0;  // N

  double expected(double n) const;  // E[S] at n spp
  double sd(double n) const;        // sd[S] at n spp
  double bound(double n, double z) const { return expected(n) + z * sd(n); }
  // Of E[S] at n spp, the part the stored reference's own noise explains: n / (n + N).
  double reference_share(double n) const;
};

}  // namespace pt::error_model
