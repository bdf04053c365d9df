// The statistics toolkit (tests/support/statistics.h), each function on its
// own against distributions whose answer is known: the graded suites are
// only as trustworthy as these functions.
//
// Thresholds here follow the same rule as the graded tests: a correct
// toolkit fails each test with probability far below 1e-4. Calibration tests
// count how often a level-0.05 test rejects a true null over many repetitions:
// the count is Binomial(reps, 0.05) for a calibrated test, and the bounds are
// 5 to 6 of its standard deviations away from the mean.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/rng.h"
#include "core/sampling.h"
#include "support/seed.h"
#include "support/statistics.h"

namespace pt {
namespace {

using stats::RunningStats;

// Standard normal variates by Box-Muller from the framework's generator.
class Normal {
 public:
  explicit Normal(uint64_t seed) : rng_(seed) {}
  double operator()() {
    double u1 = 1.0 - rng_.uniform(), u2 = rng_.uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
  }
  Rng& rng() { return rng_; }

 private:
  Rng rng_;
};

double exponential(Rng& rng) { return -std::log(1.0 - rng.uniform()); }

// ---- RunningStats ----------------------------------------------------------

TEST(RunningStats, MatchesTwoPassMomentsEvenWithALargeOffset) {
  Normal normal(test::seed(11));
  std::vector<double> xs;
  for (int i = 0; i < 20000; ++i) xs.push_back(1e6 + 3.0 * normal() + (i % 7 == 0 ? exponential(normal.rng()) : 0));
  RunningStats s;
  for (double x : xs) s.add(x);
  // Two-pass reference in long double.
  long double mean = 0;
  for (double x : xs) mean += x;
  mean /= xs.size();
  long double m2 = 0, m3 = 0, m4 = 0;
  for (double x : xs) {
    long double d = x - mean;
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  const double n = double(xs.size());
  EXPECT_EQ(s.count(), int64_t(xs.size()));
  EXPECT_NEAR(s.mean(), double(mean), 1e-13 * 1e6);  // 1e6 offset: the last bits of a double
  EXPECT_NEAR(s.variance(), double(m2 / (n - 1)), 1e-9 * double(m2 / n));
  EXPECT_NEAR(s.central_moment3(), double(m3 / n), 1e-7 * std::abs(double(m3 / n)) + 1e-9);
  EXPECT_NEAR(s.central_moment4(), double(m4 / n), 1e-8 * double(m4 / n));
  EXPECT_NEAR(s.standard_error(), std::sqrt(double(m2 / (n - 1)) / n), 1e-12);
  EXPECT_NEAR(s.kurtosis(), double(n * m4 / (m2 * m2)), 1e-8);

  // Merging two halves gives the moments of the whole.
  RunningStats a, b;
  for (size_t i = 0; i < xs.size(); ++i) (i < 7000 ? a : b).add(xs[i]);
  a.merge(b);
  EXPECT_EQ(a.count(), s.count());
  EXPECT_NEAR(a.mean(), s.mean(), 1e-13 * 1e6);
  EXPECT_NEAR(a.variance(), s.variance(), 1e-9 * s.variance());
  EXPECT_NEAR(a.central_moment3(), s.central_moment3(), 1e-7 * std::abs(s.central_moment3()) + 1e-9);
  EXPECT_NEAR(a.central_moment4(), s.central_moment4(), 1e-8 * s.central_moment4());
  EXPECT_EQ(a.min(), s.min());
  EXPECT_EQ(a.max(), s.max());
}

TEST(RunningStats, CountsNonFiniteSamplesApart) {
  RunningStats s;
  s.add(1.0);
  s.add(std::nan(""));
  s.add(INFINITY);
  s.add(3.0);
  EXPECT_EQ(s.count(), 2);
  EXPECT_EQ(s.nonfinite_count(), 2);
  EXPECT_DOUBLE_EQ(s.mean(), 2.0);
  EXPECT_DOUBLE_EQ(s.variance(), 2.0);
  EXPECT_FALSE(stats::mean_matches(s, 2.0, 1e-5)) << "a NaN sample must fail a mean test";
}

TEST(RunningStats, KurtosisAndVarianceOfVarianceOfKnownLaws) {
  // Normal: kurtosis 3 and Var(s^2) = 2 sigma^4 / (n - 1). Exponential(1):
  // kurtosis 9, Var(s^2) ~ (9 - 1) / n. With n = 1e6 the sample kurtosis has
  // standard error sqrt(24 / n) = 0.005 for the normal and about 0.1 for the
  // exponential (whose 8th moment is 40320): bounds at 10 of them.
  const int n = 1000000;
  Normal normal(test::seed(12));
  RunningStats g, e;
  for (int i = 0; i < n; ++i) {
    g.add(2.0 * normal());
    e.add(exponential(normal.rng()));
  }
  EXPECT_NEAR(g.kurtosis(), 3.0, 0.05);
  EXPECT_NEAR(g.variance_of_variance() / (2.0 * 16.0 / (n - 1)), 1.0, 0.05);  // sigma^4 = 16
  EXPECT_NEAR(e.kurtosis(), 9.0, 1.0);
  EXPECT_NEAR(e.variance_of_variance() / (8.0 / n), 1.0, 0.15);
}

// ---- Distribution functions ------------------------------------------------

TEST(Distributions, KnownValues) {
  EXPECT_NEAR(stats::normal_cdf(0.0), 0.5, 1e-15);
  EXPECT_NEAR(stats::normal_cdf(1.959963984540054), 0.975, 1e-12);
  EXPECT_NEAR(stats::normal_quantile(0.975), 1.959963984540054, 1e-12);
  EXPECT_NEAR(stats::normal_sf(8.0), 6.220960574271785e-16, 1e-27);  // no cancellation in the tail
  // Student t with 1 dof is the Cauchy law: cdf(t) = 1/2 + atan(t) / pi.
  for (double t : {-3.0, -0.5, 0.0, 1.0, 10.0})
    EXPECT_NEAR(stats::student_t_cdf(t, 1.0), 0.5 + std::atan(t) / kPi, 1e-12) << "t " << t;
  EXPECT_NEAR(stats::student_t_sf(2.0, 1e7), stats::normal_sf(2.0), 1e-7);  // t tends to the normal
  // Chi-square with 2 dof: sf(x) = exp(-x / 2).
  for (double x : {0.1, 1.0, 10.0, 80.0}) EXPECT_NEAR(stats::chi_square_sf(x, 2.0), std::exp(-x / 2), 1e-14) << x;
  EXPECT_NEAR(stats::chi_square_cdf(3.841458820694124, 1.0), 0.95, 1e-12);
}

TEST(Distributions, SidakCorrection) {
  EXPECT_DOUBLE_EQ(stats::sidak_alpha(0.05, 1), 0.05);
  for (int m : {2, 5, 100}) {
    const double a = stats::sidak_alpha(0.05, m);
    EXPECT_NEAR(1.0 - std::pow(1.0 - a, m), 0.05, 1e-14) << m;
    EXPECT_GT(a, 0.05 / m) << "Sidak is slightly less strict than Bonferroni";
  }
  EXPECT_NEAR(stats::sidak_alpha(1e-5, 10), 1e-6, 1e-10);
}

// ---- Mean tests --------------------------------------------------------------

TEST(MeanTests, AcceptTheTrueMeanAndRejectAShiftedOne) {
  // n = 1e5: se = 1/316 for unit variance. A true mean is accepted unless
  // |t| > 4.4 (alpha = 1e-5); a shift of 0.05 is 15.8 standard errors.
  const int n = 100000;
  Normal normal(test::seed(13));
  RunningStats g, e;
  for (int i = 0; i < n; ++i) {
    g.add(0.3 + normal());
    e.add(exponential(normal.rng()));  // skewed: the CLT still gives the t test at this n
  }
  EXPECT_TRUE(stats::mean_matches(g, 0.3, 1e-5, "normal"));
  EXPECT_TRUE(stats::mean_matches(e, 1.0, 1e-5, "exponential"));
  EXPECT_TRUE(stats::check(stats::z_test_mean(g, 0.3, 1.0, 1e-5, "normal, known sigma")));
  EXPECT_FALSE(stats::mean_matches(g, 0.35, 1e-5, "normal shifted"));
  EXPECT_FALSE(stats::mean_matches(e, 1.05, 1e-5, "exponential shifted"));
  EXPECT_FALSE(stats::check(stats::z_test_mean(g, 0.25, 1.0, 1e-5)));

  // The failure message states everything needed to judge it.
  std::string msg = stats::mean_matches(g, 0.35, 1e-5, "irradiance").message();
  for (const char* part : {"irradiance", "n=100000", "mean=", "expected=0.35", "standard error=", "t=", "p=",
                           "alpha=1e-05"})
    EXPECT_NE(msg.find(part), std::string::npos) << "missing '" << part << "' in: " << msg;
}

TEST(MeanTests, PValuesAreUniformUnderTheNull) {
  // 4000 t tests of 20 normal samples (where Student's law is exact), and 4000
  // z tests with the true sigma: each rejects at level 0.05 with probability
  // exactly 0.05, so the count is Binomial(4000, 0.05): mean 200, sd 13.8.
  // Bounds at 6 sd (false alarm ~2e-9). A z test with the *sample* sigma at
  // n = 20 would reject about 7% of the time: that is why the t law is used.
  Normal normal(test::seed(14));
  int t_rejects = 0, z_rejects = 0;
  for (int rep = 0; rep < 4000; ++rep) {
    RunningStats s;
    for (int i = 0; i < 20; ++i) s.add(5.0 + 2.0 * normal());
    t_rejects += !stats::t_test_mean(s, 5.0, 0.05).passed();
    z_rejects += !stats::z_test_mean(s, 5.0, 2.0, 0.05).passed();
  }
  EXPECT_GE(t_rejects, 117);
  EXPECT_LE(t_rejects, 283);
  EXPECT_GE(z_rejects, 117);
  EXPECT_LE(z_rejects, 283);
}

TEST(MeanTests, ExactEstimatorsPassOnlyAtTheirValue) {
  RunningStats s;
  for (int i = 0; i < 100; ++i) s.add(0.7 * (1.0 + 1e-15 * (i % 3)));  // rounding-level scatter
  EXPECT_TRUE(stats::mean_matches(s, 0.7, 1e-5));
  EXPECT_FALSE(stats::mean_matches(s, 0.7001, 1e-5));
  RunningStats zero;
  for (int i = 0; i < 10; ++i) zero.add(0.0);
  EXPECT_TRUE(stats::mean_matches(zero, 0.0, 1e-5));
  EXPECT_FALSE(stats::mean_matches(zero, 1e-3, 1e-5));
  RunningStats none;
  EXPECT_FALSE(stats::mean_matches(none, 0.0, 1e-5)) << "no samples is no evidence";
}

TEST(MeanTests, PooledRelativeBiasFindsACommonFactor) {
  // Eight configurations of n = 2e4 normal samples with means 1..8 and sd
  // equal to the mean: relative se 0.71% each, 0.25% pooled (sqrt 8 times
  // smaller). (1) True means: accepted unless |z| > 4.4 (alpha = 1e-5).
  // (2) Every mean 3% high: 4.2 standard errors of each configuration (a
  // separate test at alpha 1e-5 / 8 misses it about half the time), 12 of
  // the pool: rejected but for a chance of about 1e-13. (3) An exact
  // configuration (no spread) and one whose mean is 0 are left out of the
  // pool; a NaN sample fails it.
  const int n = 20000;
  Normal normal(test::seed(15));
  std::vector<RunningStats> fair(8), biased(8);
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < n; ++i) {
      const double mu = k + 1.0, x = mu * (1.0 + normal());
      fair[size_t(k)].add(x);
      biased[size_t(k)].add(1.03 * x);
    }
  std::vector<stats::MeanAgainst> f, b;
  for (int k = 0; k < 8; ++k) {
    f.push_back({&fair[size_t(k)], k + 1.0});
    b.push_back({&biased[size_t(k)], k + 1.0});
  }
  const stats::MeanTestResult pooled = stats::pooled_relative_bias(f, 1e-5, "fair");
  EXPECT_TRUE(stats::check(pooled));
  EXPECT_NEAR(pooled.standard_error, 0.0025, 0.0002) << "1 / sqrt(8 (1 / 0.00707)^2)";
  EXPECT_FALSE(stats::check(stats::pooled_relative_bias(b, 1e-5, "3% high")));

  RunningStats exact, zero, nan_sample;
  for (int i = 0; i < 10; ++i) {
    exact.add(3.0);
    zero.add(normal());
  }
  nan_sample.add(std::nan(""));
  std::vector<stats::MeanAgainst> with_exact = f;
  with_exact.push_back({&exact, 5.0});  // its own exact check would fail; the pool leaves it out
  with_exact.push_back({&zero, 0.0});
  EXPECT_TRUE(stats::check(stats::pooled_relative_bias(with_exact, 1e-5)));
  with_exact.push_back({&nan_sample, 1.0});
  EXPECT_FALSE(stats::check(stats::pooled_relative_bias(with_exact, 1e-5)));
}

// ---- Chi-square ----------------------------------------------------------------

TEST(ChiSquare, PoolsSmallCellsAndCountsDegreesOfFreedom) {
  // Expected 0.5, 1, 2, 3 pool into one cell (6.5), then 10 and 20: 3 cells, 2 dof.
  std::vector<double> obs = {1, 0, 3, 2, 12, 18}, exp = {0.5, 1, 2, 3, 10, 20};
  stats::ChiSquareResult r = stats::chi_square_test(obs, exp, 1e-5);
  EXPECT_EQ(r.dof, 2);
  EXPECT_EQ(r.pooled_cells, 4);
  const double chi2 = (6 - 6.5) * (6 - 6.5) / 6.5 + 0.4 + 0.2;
  EXPECT_NEAR(r.statistic, chi2, 1e-12);
  EXPECT_NEAR(r.p_value, std::exp(-chi2 / 2), 1e-12);
  EXPECT_TRUE(r.passed());
  // A small remainder joins the smallest regular cell: 0.5 + 1 + 10 -> one cell.
  r = stats::chi_square_test({0, 2, 9, 21}, {0.5, 1, 10, 20}, 1e-5);
  EXPECT_EQ(r.dof, 1);
  // Cells with no mass and no samples are not cells; samples where the
  // density is zero fail whatever the rest says.
  r = stats::chi_square_test({10, 0, 10}, {10, 0, 10}, 1e-5);
  EXPECT_EQ(r.dof, 1);
  r = stats::chi_square_test({10, 1, 10}, {10, 0, 10}, 1e-5);
  EXPECT_FALSE(r.passed());
  EXPECT_NE(r.failure.find("density is zero"), std::string::npos);
}

TEST(ChiSquare, IntegratesDensitiesOverCells) {
  // x * y on [0, 2] x [0, 1], 5 x 3 cells: exact cell integrals.
  stats::Grid2D g{5, 3, 0.0, 2.0, 0.0, 1.0};
  std::vector<double> v = stats::integrate_over_cells(g, [](double x, double y) { return x * y; });
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 5; ++i) {
      double xa = g.cell_x0(i), xb = g.cell_x0(i + 1), ya = g.cell_y0(j), yb = g.cell_y0(j + 1);
      EXPECT_NEAR(v[j * 5 + i], 0.25 * (xb * xb - xa * xa) * (yb * yb - ya * ya), 1e-12);
    }
  // A discontinuous density (indicator of a disk of radius 0.3 inside one
  // cell, and of one crossing cell edges): the edge is resolved to well
  // below counting noise.
  stats::Grid2D g2{7, 7, 0.0, 1.0, 0.0, 1.0};
  for (Vec2 c : {Vec2(0.5, 0.5), Vec2(0.31, 0.62)}) {
    auto disk = [c](double x, double y) { return glm::length(Vec2(x, y) - c) < 0.3 ? 1.0 : 0.0; };
    std::vector<double> d = stats::integrate_over_cells(g2, disk);
    double total = 0;
    for (double x : d) total += x;
    EXPECT_NEAR(total, kPi * 0.09, 2e-4 * kPi * 0.09) << "disk at " << c;
  }
}

// Samples (x, y) with density 2x on [0, 1] (x = sqrt(u)) and uniform y.
stats::ChiSquare2D linear_ramp_histogram(const std::string& what, int n, uint64_t seed) {
  stats::ChiSquare2D h(what, {9, 7, 0.0, 1.0, 0.0, 1.0});
  Rng rng(seed);
  for (int i = 0; i < n; ++i) h.add(std::sqrt(rng.uniform()), rng.uniform());
  return h;
}

TEST(ChiSquare, AcceptsTheTrueDensityAndRejectsWrongOnes) {
  const int n = 200000;
  stats::ChiSquare2D h = linear_ramp_histogram("ramp", n, test::seed(15));
  EXPECT_TRUE(stats::check(h.run([](double x, double) { return 2.0 * x; }, 1e-5)));
  // Wrong densities: uniform, 3x^2, and the mild (2 + 2x) / 3 (each x slice
  // off by at most a third): with 200000 samples in 63 cells (about 3000 per
  // cell) each is rejected by hundreds of standard deviations.
  for (auto [name, pdf] : std::vector<std::pair<std::string, std::function<double(double, double)>>>{
           {"uniform", [](double, double) { return 1.0; }},
           {"cubic", [](double x, double) { return 3.0 * x * x; }},
           {"mild", [](double x, double) { return (2.0 + 2.0 * x) / 3.0; }}}) {
    stats::ChiSquare2D wrong = linear_ramp_histogram("wrong_" + name, n, test::seed(16));
    stats::ChiSquareResult r = wrong.run(pdf, 1e-5);
    EXPECT_FALSE(r.passed()) << name << ": " << r.describe();
    // The failure names a folder holding the tables and the picture.
    ASSERT_FALSE(r.report_dir.empty());
    EXPECT_NE(r.describe().find(r.report_dir), std::string::npos);
    for (const char* f : {"observed.txt", "expected.txt", "summary.txt", "histogram.png"})
      EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(r.report_dir) / f)) << f;
  }
}

TEST(ChiSquare, RejectsSamplesOutsideTheDomain) {
  stats::ChiSquare2D h("outside", {3, 3, 0.0, 1.0, 0.0, 1.0});
  Rng rng(test::seed(17));
  for (int i = 0; i < 1000; ++i) h.add(rng.uniform(), rng.uniform());
  h.add(1.5, 0.5);
  stats::ChiSquareResult r = h.run([](double, double) { return 1.0; }, 1e-5);
  EXPECT_FALSE(r.passed());
  EXPECT_EQ(r.outside, 1.0);
}

TEST(ChiSquare, PValuesAreUniformUnderTheNull) {
  // 1000 tests of 2000 samples on 7 x 7 cells at level 0.05 (about 40 per
  // cell: the chi-square law of Pearson's statistic is accurate): rejections
  // ~ Binomial(1000, 0.05), mean 50, sd 6.9; bounds at 5 sd.
  Rng rng(test::seed(18));
  int rejects = 0;
  for (int rep = 0; rep < 1000; ++rep) {
    std::vector<double> obs(49, 0.0), exp(49, 2000.0 / 49);
    for (int i = 0; i < 2000; ++i) obs[std::min(48, int(rng.uniform() * 49))] += 1;
    rejects += !stats::chi_square_test(obs, exp, 0.05).passed();
  }
  EXPECT_GE(rejects, 15);
  EXPECT_LE(rejects, 85);
}

TEST(ChiSquare, DirectionalHistogramRejectsTheWrongSampler) {
  // Cosine-weighted directions tested against the uniform hemisphere pdf,
  // and uniform sphere directions against the cosine pdf: both must fail.
  Rng rng(test::seed(19));
  stats::DirectionalChiSquare cos_vs_uniform("cosine_vs_uniform_pdf", {0, 0, 1}, 21, 41, 0.0, 1.0);
  stats::DirectionalChiSquare sphere_vs_cos("sphere_vs_cosine_pdf", {0, 0, 1}, 21, 41);
  for (int i = 0; i < 100000; ++i) {
    cos_vs_uniform.add(sample_cosine_hemisphere(rng.uniform2()));
    sphere_vs_cos.add(sample_uniform_sphere(rng.uniform2()));
  }
  EXPECT_FALSE(cos_vs_uniform.run(pdf_uniform_hemisphere, 1e-5).passed());
  stats::ChiSquareResult r = sphere_vs_cos.run(pdf_cosine_hemisphere, 1e-5);
  EXPECT_FALSE(r.passed());
  EXPECT_NE(r.failure.find("density is zero"), std::string::npos) << r.describe();
}

// ---- Variance ratios -------------------------------------------------------------

TEST(VarianceRatio, NormalSamples) {
  // sd 2 vs 1: ratio 4. n = 1e5 each: se(log ratio) = sqrt(2 * 2 / 1e5) = 0.0063.
  Normal normal(test::seed(20));
  RunningStats a, b;
  for (int i = 0; i < 100000; ++i) {
    a.add(2.0 * normal());
    b.add(normal());
  }
  EXPECT_TRUE(stats::check(stats::variance_ratio_equals(a, b, 4.0, 1e-5, "4 = 4")));
  EXPECT_TRUE(stats::check(stats::variance_ratio_at_least(a, b, 3.0, 1e-5, "4 >= 3")));
  EXPECT_TRUE(stats::check(stats::variance_ratio_at_least(a, b, 4.0, 1e-5, "4 >= 4")));
  EXPECT_FALSE(stats::check(stats::variance_ratio_at_least(a, b, 5.0, 1e-5, "4 >= 5")));  // z = -35
  EXPECT_FALSE(stats::check(stats::variance_ratio_equals(a, b, 1.0, 1e-5, "4 = 1")));
  EXPECT_NEAR(stats::compare_variances(a, b).log_ratio_se, std::sqrt(4.0 / 1e5), 3e-4);
}

TEST(VarianceRatio, AtMostAKnownBound) {
  // sd 2: variance 4. n = 1e5: se(log s^2) = sqrt(2 / 1e5) = 0.0045, so a
  // bound of 4.1 (log ratio -0.025) holds, 3.8 (+0.051, z = 11) is rejected.
  Normal normal(test::seed(21));
  RunningStats a;
  for (int i = 0; i < 100000; ++i) a.add(2.0 * normal());
  EXPECT_TRUE(stats::check(stats::variance_at_most(a, 4.1, 1e-5, "4 <= 4.1")));
  EXPECT_TRUE(stats::check(stats::variance_at_most(a, 1e3, 1e-5, "4 <= 1000")));
  EXPECT_FALSE(stats::check(stats::variance_at_most(a, 3.8, 1e-5, "4 <= 3.8")));
  EXPECT_NEAR(stats::variance_at_most(a, 4.0, 1e-5).log_ratio_se, std::sqrt(2.0 / 1e5), 2e-4);
  RunningStats constant;
  for (int i = 0; i < 10; ++i) constant.add(1.5);
  EXPECT_TRUE(stats::check(stats::variance_at_most(constant, 1e-12, 1e-5, "a constant")));
}

TEST(VarianceRatio, StaysCalibratedForHeavyTailedSamplesWhereTheFTestDoesNot) {
  // Equal variances, exponential samples (kurtosis 9), n = 2000 each, 1000
  // repetitions at level 0.05. The log-ratio test has Var(log s^2) ~ 8/n and
  // uses it: rejections ~ Binomial(1000, 0.05 + small-sample error), bounded
  // by 100 (mean 50, sd 6.9: 7 sd). The F test's normal theory uses 2/n, a
  // standard error half the true one: it rejects about 1 time in 3 (at least
  // 200 in 1000 here, bound 9 sd below its rate): the reason it is not used.
  Rng rng(test::seed(21));
  int robust = 0, f_test = 0;
  const int n = 2000;
  for (int rep = 0; rep < 1000; ++rep) {
    RunningStats a, b;
    for (int i = 0; i < n; ++i) {
      a.add(exponential(rng));
      b.add(exponential(rng));
    }
    robust += !stats::variance_ratio_equals(a, b, 1.0, 0.05).passed();
    const double z = std::log(a.variance() / b.variance()) / std::sqrt(2.0 / (n - 1) + 2.0 / (n - 1));
    f_test += std::abs(z) > stats::normal_quantile(0.975);
  }
  EXPECT_LE(robust, 100);
  EXPECT_GE(robust, 10);
  EXPECT_GE(f_test, 200) << "the normal-theory F test should be badly off here";
}

TEST(VarianceRatio, RareEventSamples) {
  // The shape of hemisphere sampling of a small light: X = 100 with
  // probability 0.01, else 0 (kurtosis ~ 1/p = 100). Two independent samples
  // of n = 2e5 (2000 events each): the test accepts their equality, and
  // rejects a ratio of 2 (se(log ratio) = sqrt(2 * 99 / 2e5) = 0.031, log 2 =
  // 22 se).
  Rng rng(test::seed(22));
  RunningStats a, b;
  for (int i = 0; i < 200000; ++i) {
    a.add(rng.coin_flip(0.01) ? 100.0 : 0.0);
    b.add(rng.coin_flip(0.01) ? 100.0 : 0.0);
  }
  EXPECT_TRUE(stats::check(stats::variance_ratio_equals(a, b, 1.0, 1e-5, "rare events")));
  EXPECT_FALSE(stats::check(stats::variance_ratio_equals(a, b, 2.0, 1e-5, "rare events vs 2")));
  EXPECT_NEAR(stats::compare_variances(a, b).log_ratio_se, std::sqrt(2.0 * 99.0 / 2e5), 0.004);
}

TEST(VarianceRatio, ZeroVarianceSides) {
  RunningStats a, b;
  for (int i = 0; i < 100; ++i) {
    a.add(i % 2);
    b.add(1.0);
  }
  EXPECT_TRUE(stats::check(stats::variance_ratio_at_least(a, b, 1000.0, 1e-5)));  // infinite ratio
  EXPECT_FALSE(stats::check(stats::variance_ratio_at_least(b, a, 1e-3, 1e-5)));   // zero ratio
}

}  // namespace
}  // namespace pt
