#pragma once
// The statistics toolkit of the test suites: every distribution test and every
// estimator-mean or estimator-variance test goes through this one header, so
// that each threshold in the suites is a significance level (a probability
// that a correct solution fails) rather than a tuned tolerance.
//
//   RunningStats             Welford running mean / variance, plus the third
//                            and fourth central moments (Terriberry's update),
//                            which give the variance of the sample variance.
//   t_test_mean, z_test_mean two-sided test of a sample mean against a closed
//                            form; mean_matches() wraps it as an
//                            ::testing::AssertionResult whose message states
//                            n, mean, expected, standard error, t or z, p, alpha.
//   ChiSquare2D              chi-square goodness of fit of a 2-D histogram
//                            against a density integrated over every cell
//                            (adaptive Simpson), cells with expected count < 5
//                            pooled; writes the observed and expected tables
//                            and a PNG to test_output/ when the fit is rejected.
//   DirectionalChiSquare     the same for unit vectors on a (cos theta, phi)
//                            grid, where a pdf per unit solid angle is exactly
//                            the density on the grid (d omega = d cos d phi).
//   variance_ratio_*         two-sample comparison of variances that stays
//                            valid for non-normal, heavy-tailed samples.
//   sidak_alpha              per-test level of m tests that share a budget.
//
// Distribution functions come from Boost.Math (header only). Run a test binary
// with PT_STATS_VERBOSE=1 in the environment to print every check's
// statistics, passed or failed, and with PT_STATS_REPORT=1 to write every
// chi-square test's tables and picture, not only the failing ones'.
//
// How the suites use it: each graded test is allowed a false-failure
// probability below 1e-4 (the README: How you are graded). A test that makes m statistical
// checks gives each one sidak_alpha(alpha_test, m), so that a correct solution
// fails the whole test with probability at most alpha_test. The tests take
// alpha_test = 1e-5, ten times below the budget, so that the large-sample
// approximations (central limit theorem for means, the chi-square law for the
// Pearson statistic, the delta method for variance ratios) may be off by a
// factor of ten in the far tail without breaking the 1e-4 promise.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/vec.h"

namespace pt::stats {

// ---------------------------------------------------------------------------
// Running moments

// Welford's one-pass mean and variance, extended to the third and fourth
// central moments (Terriberry 2007; Pebay 2008 for merging). Numerically
// stable: no sum of squares of large numbers is ever formed. Non-finite
// samples are counted but kept out of the moments; every test built on this
// class fails when any sample was non-finite.
class RunningStats {
 public:
  void add(double x);
  void merge(const RunningStats& other);  // as if every sample of other were added

  int64_t count() const { return n_; }             // finite samples
  int64_t nonfinite_count() const { return bad_; }  // NaN or infinite samples seen
  double mean() const { return mean_; }
  // Unbiased sample variance s^2 = M2 / (n - 1) (0 for fewer than 2 samples).
  double variance() const { return n_ > 1 ? m2_ / double(n_ - 1) : 0.0; }
  double std_dev() const;
  // Standard error of the mean, s / sqrt(n).
  double standard_error() const;
  // Central moments with 1/n normalisation: m_k = (1/n) sum (x - mean)^k.
  double central_moment2() const { return n_ > 0 ? m2_ / double(n_) : 0.0; }
  double central_moment3() const { return n_ > 0 ? m3_ / double(n_) : 0.0; }
  double central_moment4() const { return n_ > 0 ? m4_ / double(n_) : 0.0; }
  // Kurtosis m4 / m2^2 (3 for a normal, 9 for an exponential, about 1/p for a
  // rare event of probability p: the estimators of this course are heavy tailed).
  double kurtosis() const;
  // Estimate of Var(s^2) = (mu4 - sigma^4 (n - 3) / (n - 1)) / n, with mu4 and
  // sigma^4 replaced by m4 and s^4. For a normal this is about 2 sigma^4 / n,
  // but it grows with the kurtosis, which is why a plain F test (which assumes
  // 2 sigma^4 / n) is wrong for estimator samples.
  double variance_of_variance() const;
  double min() const { return min_; }
  double max() const { return max_; }

 private:
  int64_t n_ = 0, bad_ = 0;
  double mean_ = 0.0, m2_ = 0.0, m3_ = 0.0, m4_ = 0.0;
  double min_ = kInf, max_ = -kInf;
};

// ---------------------------------------------------------------------------
// Distribution functions (Boost.Math) and multiple testing

double normal_cdf(double x);
double normal_sf(double x);         // 1 - normal_cdf(x), accurate far in the upper tail
double normal_quantile(double p);   // inverse of normal_cdf
double student_t_cdf(double t, double dof);
double student_t_sf(double t, double dof);  // 1 - cdf, accurate in the tail
double chi_square_cdf(double x, double dof);
double chi_square_sf(double x, double dof);  // P(X >= x): the p-value of a chi-square statistic

// Šidák correction: the level of each of m independent tests such that all m
// pass with probability 1 - alpha_family when every null hypothesis holds:
// 1 - (1 - alpha_family)^(1/m). (Slightly above Bonferroni's alpha/m; valid
// as an upper bound on the family-wise error for independent tests, which is
// what tests with separate seeds are.)
double sidak_alpha(double alpha_family, int m);

// ---------------------------------------------------------------------------
// Means against closed forms

// Deviations |mean - expected| up to this much are treated as zero: floating
// point rounding of an estimator that is exact (zero variance, e.g. a point
// light, or f cos / pdf of a cosine-sampled Lambertian) would otherwise give
// an infinite z. The default, 1e-9 relative plus 1e-12 absolute, is far below
// any bias a test looks for.
double default_rounding_tolerance(double expected);

struct MeanTestResult {
  std::string method;  // "t" or "z"
  std::string what;    // what was measured, for the message
  int64_t n = 0, nonfinite = 0;
  double mean = 0, expected = 0, standard_error = 0, statistic = 0, p_value = 1, alpha = 0, tolerance = 0;
  bool passed() const { return nonfinite == 0 && n > 0 && p_value >= alpha; }
  std::string describe() const;  // one line: n, mean, expected, se, t or z, p, alpha
};

// Student's t test of H0 "E[X] = expected" with the sample standard deviation,
// two-sided, n - 1 degrees of freedom. With the sample sizes of the suites
// (n >= 1e4) t and z coincide; the t form is the honest one for small n.
MeanTestResult t_test_mean(const RunningStats& s, double expected, double alpha, const std::string& what = "",
                           double tolerance = -1.0);
// z test with a known standard deviation sigma of one sample (e.g. from a
// closed form): se = sigma / sqrt(n), two-sided, normal p-value.
MeanTestResult z_test_mean(const RunningStats& s, double expected, double sigma, double alpha,
                           const std::string& what = "", double tolerance = -1.0);

// EXPECT_TRUE(stats::mean_matches(s, expected, alpha, "irradiance at p0")).
::testing::AssertionResult mean_matches(const RunningStats& s, double expected, double alpha,
                                        const std::string& what = "");
::testing::AssertionResult check(const MeanTestResult& r);

// One sample of estimates and the closed form of its mean.
struct MeanAgainst {
  const RunningStats* sample;
  double expected;
};

// A bias shared by several configurations (a constant factor wrong in all of
// them): a two-sided z test of H0 "the means have no common relative bias".
// The statistic is the inverse-variance weighted mean of the relative
// deviations (mean_i - expected_i) / expected_i, with standard error
// 1 / sqrt(sum_i (expected_i / se_i)^2): smaller than every configuration's
// own, so that a test of m configurations detects a bias common to all of
// them that each separate test would miss. The result reads as a mean test
// of the pooled ratio mean/expected against 1. Configurations whose expected
// value is 0, or whose standard error is 0 (an exact estimator), are left out:
// their own checks judge them. Any non-finite sample fails it.
MeanTestResult pooled_relative_bias(const std::vector<MeanAgainst>& samples, double alpha,
                                    const std::string& what = "");

// ---------------------------------------------------------------------------
// Variances of two independent samples

// Comparison of Var(A) and Var(B) that does not assume normality. By the
// delta method, log s^2 is asymptotically normal with variance
// Var(s^2) / sigma^4 = (kappa - (n - 3) / (n - 1)) / n, where kappa is the
// kurtosis (estimated from the fourth central moment, see RunningStats). So
//   log(s_A^2 / s_B^2) ~ N(log(sigma_A^2 / sigma_B^2), se^2),
//   se^2 = Var(s_A^2) / s_A^4 + Var(s_B^2) / s_B^4.
// A plain F test uses se^2 = 2 / (n_A - 1) + 2 / (n_B - 1), the normal-theory
// value: for an exponential (kappa = 9) it under-states se by a factor of 2
// and rejects a true null several times too often; for the rare-event samples
// of hemisphere sampling a small light, by far more. This large-sample test
// needs a finite fourth moment (every bounded estimator has one) and enough
// samples for the kurtosis to be estimated: thousands of samples, and enough
// of the rare events (non-zero samples) to be seen many times over.
struct VarianceRatioResult {
  std::string what;
  int64_t n_a = 0, n_b = 0, nonfinite = 0;
  double var_a = 0, var_b = 0, kurtosis_a = 0, kurtosis_b = 0;
  double ratio = 0;         // s_A^2 / s_B^2
  double log_ratio_se = 0;  // se of log(ratio)
  double hypothesis = 0;    // the ratio under H0
  double statistic = 0;     // z = (log ratio - log hypothesis) / se
  double p_value = 1, alpha = 0;
  bool passed() const { return nonfinite == 0 && p_value >= alpha; }
  std::string describe() const;
};

VarianceRatioResult compare_variances(const RunningStats& a, const RunningStats& b);

// H0 "Var(A) / Var(B) >= factor", one-sided: rejected (the check fails) only
// when the data show at level alpha that the ratio is below factor, i.e. when
// log(ratio) + z_{1-alpha} se < log(factor). A correct solution whose true
// ratio is at least factor therefore fails with probability at most alpha.
VarianceRatioResult variance_ratio_at_least(const RunningStats& a, const RunningStats& b, double factor,
                                            double alpha, const std::string& what = "");
// H0 "Var(A) <= bound" for a bound known exactly (a closed form, a
// quadrature), one-sided: rejected only when the data show at level alpha
// that the variance is above it, i.e. when log(s^2) - z_{1-alpha} se >
// log(bound), se = the standard error of log(s^2) from A's fourth moment
// (reported as Var(B) = bound, n_B = 0).
VarianceRatioResult variance_at_most(const RunningStats& a, double bound, double alpha, const std::string& what = "");
// H0 "Var(A) / Var(B) = factor", two-sided.
VarianceRatioResult variance_ratio_equals(const RunningStats& a, const RunningStats& b, double factor, double alpha,
                                          const std::string& what = "");
::testing::AssertionResult check(const VarianceRatioResult& r);

// ---------------------------------------------------------------------------
// Chi-square goodness of fit

// Pearson's chi-square of observed against expected counts. Cells whose
// expected count is below min_expected are pooled (in increasing order of
// expected count, until each pool reaches min_expected; a remainder joins the
// last pool), so that the chi-square law of the statistic holds. A cell with
// observed > 0 where the expected count is zero (the density is zero over the
// whole cell) fails outright: no amount of noise explains a sample where the
// pdf says none can be. Degrees of freedom: cells after pooling - 1.
struct ChiSquareResult {
  std::string what;
  double statistic = 0, p_value = 1, alpha = 0;
  int dof = 0, cells = 0, pooled_cells = 0;  // pooled_cells: cells merged into pools
  double samples = 0, outside = 0;          // outside: samples that fell outside the grid
  std::string failure;     // a reason that overrides the p-value ("sample where the pdf is 0")
  std::string report_dir;  // where the tables and the PNG were written (on failure)
  bool passed() const { return failure.empty() && p_value >= alpha; }
  std::string describe() const;
};

ChiSquareResult chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected,
                                double alpha, double min_expected = 5.0);

// A regular nx x ny grid over [x0, x1] x [y0, y1]; cell (i, j) has index j * nx + i.
struct Grid2D {
  int nx = 1, ny = 1;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  int cell(double x, double y) const;  // -1 when (x, y) is outside
  double cell_x0(int i) const { return x0 + (x1 - x0) * i / nx; }
  double cell_y0(int j) const { return y0 + (y1 - y0) * j / ny; }
};

// Integral of density over every cell of the grid, by adaptive 2-D Simpson
// quadrature (a quadtree per cell). Each cell is first cut into
// `subdivisions` x `subdivisions` rectangles sampled on 5 x 5 points (so a
// feature wider than 1/16 of a cell, such as a small light or the corner of
// one, is not stepped over); a rectangle is split, down to max_depth levels,
// while its 3 x 3 rule and the sum of its quarters' rules differ by more than
// rel_eps of the cell's integral, or while its samples are zero in some
// places and not in others (an edge of the density's support, where the
// Simpson error estimate means nothing). Along such an edge the leaves end
// 1/1024 of a cell wide: the error there is ~1e-3 of the cell's count, a
// tenth of the counting noise of a cell holding 10^4 samples, less in
// smaller cells.
std::vector<double> integrate_over_cells(const Grid2D& grid, const std::function<double(double, double)>& density,
                                         int subdivisions = 4, double rel_eps = 1e-6, int max_depth = 8);

// A 2-D histogram and its chi-square test against a density on the grid's
// domain (probability per unit x*y area, integrating to 1 over the whole
// domain, and to less when some probability lies outside the grid).
class ChiSquare2D {
 public:
  // `what` names the test in messages and in the report folder.
  ChiSquare2D(std::string what, const Grid2D& grid);
  void add(double x, double y);
  const Grid2D& grid() const { return grid_; }
  const std::vector<double>& observed() const { return observed_; }
  double samples() const { return total_; }
  // Expected counts are samples() times the density integrated over each
  // cell. The grid must hold all of the density's mass: a sample outside it
  // is a failure (choose the domain so that none can fall outside).
  // `subdivisions` is that of integrate_over_cells: raise it when the
  // density's support has parts thinner than 1/16 of a cell (a light seen
  // edge-on is a thin band, and its corners thin slivers).
  ChiSquareResult run(const std::function<double(double, double)>& density, double alpha, int subdivisions = 4);
  // Where a failing run writes: test_output/<Suite>.<Test>/<what>/ under the
  // working directory (observed.txt, expected.txt, summary.txt, histogram.png:
  // observed | expected | (observed - expected) / sqrt(expected)).
  std::string report_dir() const;
  // Writes the report now (run() does it on failure; tests may want it anyway).
  void write_report(const std::vector<double>& expected, const ChiSquareResult& r) const;
  std::string x_label = "x", y_label = "y";  // the axes, in the report's text

 private:
  std::string what_;
  Grid2D grid_;
  std::vector<double> observed_;
  double total_ = 0, outside_ = 0;
};

// Unit vectors binned by (cos theta, phi) in a frame whose z axis is `axis`:
// x = phi in [0, 2 pi), y = cos theta in [cos_min, cos_max] (so the report's
// images have the pole at the top and the horizon lower down). The map has unit
// Jacobian, so the expected count of a cell is N times the pdf per solid
// angle integrated over the cell in (cos theta, phi). Use odd resolutions, so
// that no cell boundary sits on a symmetry plane (phi = pi, cos theta = 0)
// where an error could cancel between neighbours.
class DirectionalChiSquare {
 public:
  DirectionalChiSquare(std::string what, const Vec3& axis, int n_cos, int n_phi, double cos_min = -1.0,
                       double cos_max = 1.0);
  void add(const Vec3& w);  // w need not be normalised (it is, before binning)
  ChiSquareResult run(const std::function<double(const Vec3&)>& pdf_solid_angle, double alpha, int subdivisions = 4);
  Vec3 direction(double cos_theta, double phi) const;  // world direction of a grid point
  const ChiSquare2D& histogram() const { return hist_; }

 private:
  Frame frame_;
  ChiSquare2D hist_;
};

::testing::AssertionResult check(const ChiSquareResult& r);

}  // namespace pt::stats
