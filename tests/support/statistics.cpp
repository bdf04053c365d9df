#include "support/statistics.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <sstream>

#include "render/image.h"
#include "io/image_file.h"

namespace pt::stats {

// ---------------------------------------------------------------------------
// RunningStats

void RunningStats::add(double x) {
  if (!std::isfinite(x)) {
    ++bad_;
    return;
  }
  // Terriberry's one-pass update of the central sums M2, M3, M4 (in this order:
  // each uses the previous values of the lower ones).
  const double n1 = double(n_);
  ++n_;
  const double n = double(n_);
  const double delta = x - mean_;
  const double delta_n = delta / n;
  const double delta_n2 = delta_n * delta_n;
  const double term1 = delta * delta_n * n1;
  mean_ += delta_n;
  m4_ += term1 * delta_n2 * (n * n - 3.0 * n + 3.0) + 6.0 * delta_n2 * m2_ - 4.0 * delta_n * m3_;
  m3_ += term1 * delta_n * (n - 2.0) - 3.0 * delta_n * m2_;
  m2_ += term1;
  min_ = std::min(min_, x);
  max_ = std::max(max_, x);
}

void RunningStats::merge(const RunningStats& o) {
  bad_ += o.bad_;
  if (o.n_ == 0) return;
  if (n_ == 0) {
    const int64_t bad = bad_;
    *this = o;
    bad_ = bad;
    return;
  }
  // Pebay (2008), pairwise update of the central sums.
  const double na = double(n_), nb = double(o.n_), n = na + nb;
  const double d = o.mean_ - mean_, d2 = d * d, d3 = d2 * d, d4 = d2 * d2;
  const double m2 = m2_ + o.m2_ + d2 * na * nb / n;
  const double m3 = m3_ + o.m3_ + d3 * na * nb * (na - nb) / (n * n) + 3.0 * d * (na * o.m2_ - nb * m2_) / n;
  const double m4 = m4_ + o.m4_ + d4 * na * nb * (na * na - na * nb + nb * nb) / (n * n * n) +
                    6.0 * d2 * (na * na * o.m2_ + nb * nb * m2_) / (n * n) + 4.0 * d * (na * o.m3_ - nb * m3_) / n;
  mean_ += d * nb / n;
  m2_ = m2;
  m3_ = m3;
  m4_ = m4;
  n_ += o.n_;
  min_ = std::min(min_, o.min_);
  max_ = std::max(max_, o.max_);
}

double RunningStats::std_dev() const { return std::sqrt(variance()); }

double RunningStats::standard_error() const { return n_ > 0 ? std::sqrt(variance() / double(n_)) : 0.0; }

double RunningStats::kurtosis() const { return m2_ > 0.0 ? double(n_) * m4_ / (m2_ * m2_) : 0.0; }

double RunningStats::variance_of_variance() const {
  if (n_ < 4) return kInf;
  const double n = double(n_), s2 = variance();
  const double v = (central_moment4() - s2 * s2 * (n - 3.0) / (n - 1.0)) / n;
  return std::max(v, 0.0);
}

// ---------------------------------------------------------------------------
// Distribution functions

namespace bm = boost::math;

double normal_cdf(double x) { return bm::cdf(bm::normal_distribution<double>(), x); }
double normal_sf(double x) { return bm::cdf(bm::complement(bm::normal_distribution<double>(), x)); }
double normal_quantile(double p) { return bm::quantile(bm::normal_distribution<double>(), p); }
double student_t_cdf(double t, double dof) { return bm::cdf(bm::students_t_distribution<double>(dof), t); }
double student_t_sf(double t, double dof) {
  return bm::cdf(bm::complement(bm::students_t_distribution<double>(dof), t));
}
double chi_square_cdf(double x, double dof) { return bm::cdf(bm::chi_squared_distribution<double>(dof), x); }
double chi_square_sf(double x, double dof) {
  return bm::cdf(bm::complement(bm::chi_squared_distribution<double>(dof), x));
}

double sidak_alpha(double alpha_family, int m) {
  if (m <= 1) return alpha_family;
  // -expm1(log1p(-a) / m) is 1 - (1 - a)^(1/m) without cancellation for small a.
  return -std::expm1(std::log1p(-alpha_family) / double(m));
}

// ---------------------------------------------------------------------------
// Means

double default_rounding_tolerance(double expected) { return 1e-9 * std::abs(expected) + 1e-12; }

namespace {

std::string fmt(double v) {
  std::ostringstream os;
  os << std::setprecision(6) << v;
  return os.str();
}

// p-value of a deviation dev with standard error se; `tail` maps a
// non-negative statistic to its upper-tail probability.
void finish_mean_test(MeanTestResult& r, const std::function<double(double)>& tail) {
  double dev = std::abs(r.mean - r.expected) - r.tolerance;
  if (dev <= 0.0) {
    r.statistic = 0.0;
    r.p_value = 1.0;
  } else if (r.standard_error <= 0.0) {
    r.statistic = kInf;
    r.p_value = 0.0;
  } else {
    r.statistic = std::copysign(dev / r.standard_error, r.mean - r.expected);
    r.p_value = std::min(1.0, 2.0 * tail(std::abs(r.statistic)));
  }
  if (r.n == 0 || r.nonfinite > 0 || !std::isfinite(r.mean)) r.p_value = 0.0;
}

}  // namespace

std::string MeanTestResult::describe() const {
  std::ostringstream os;
  if (!what.empty()) os << what << ": ";
  os << "n=" << n << " mean=" << fmt(mean) << " expected=" << fmt(expected) << " (mean/expected="
     << (expected != 0.0 ? fmt(mean / expected) : std::string("-")) << ") standard error=" << fmt(standard_error)
     << " " << method << "=" << fmt(statistic) << " p=" << fmt(p_value) << " alpha=" << fmt(alpha)
     << " (two-sided " << method << " test";
  if (tolerance > 0.0) os << ", deviations below " << fmt(tolerance) << " count as rounding";
  os << ")";
  if (nonfinite > 0) os << "; " << nonfinite << " samples were NaN or infinite";
  if (n == 0) os << "; no samples";
  return os.str();
}

namespace {
// What both mean tests record before their standard error and p-value.
MeanTestResult start_mean_test(const char* method, const RunningStats& s, double expected, double alpha,
                               const std::string& what, double tolerance) {
  MeanTestResult r;
  r.method = method;
  r.what = what;
  r.n = s.count();
  r.nonfinite = s.nonfinite_count();
  r.mean = s.mean();
  r.expected = expected;
  r.alpha = alpha;
  r.tolerance = tolerance >= 0.0 ? tolerance : default_rounding_tolerance(expected);
  return r;
}
}  // namespace

MeanTestResult t_test_mean(const RunningStats& s, double expected, double alpha, const std::string& what,
                           double tolerance) {
  MeanTestResult r = start_mean_test("t", s, expected, alpha, what, tolerance);
  r.standard_error = s.standard_error();
  const double dof = std::max<double>(1.0, double(r.n - 1));
  finish_mean_test(r, [dof](double t) { return student_t_sf(t, dof); });
  return r;
}

MeanTestResult z_test_mean(const RunningStats& s, double expected, double sigma, double alpha,
                           const std::string& what, double tolerance) {
  MeanTestResult r = start_mean_test("z", s, expected, alpha, what, tolerance);
  r.standard_error = r.n > 0 ? sigma / std::sqrt(double(r.n)) : 0.0;
  finish_mean_test(r, [](double z) { return normal_sf(z); });
  return r;
}

MeanTestResult pooled_relative_bias(const std::vector<MeanAgainst>& samples, double alpha, const std::string& what) {
  MeanTestResult r;
  r.method = "pooled z";
  r.what = what;
  r.expected = 1.0;
  r.alpha = alpha;
  r.tolerance = default_rounding_tolerance(1.0);
  double weight = 0.0, weighted = 0.0;
  for (const MeanAgainst& m : samples) {
    r.n += m.sample->count();
    r.nonfinite += m.sample->nonfinite_count();
    const double rse = m.expected != 0.0 ? m.sample->standard_error() / std::abs(m.expected) : 0.0;
    if (!(rse > 0.0)) continue;
    const double w = 1.0 / (rse * rse);
    weight += w;
    weighted += w * (m.sample->mean() - m.expected) / m.expected;
  }
  r.mean = weight > 0.0 ? 1.0 + weighted / weight : 1.0;
  r.standard_error = weight > 0.0 ? 1.0 / std::sqrt(weight) : 0.0;
  finish_mean_test(r, [](double z) { return normal_sf(z); });
  return r;
}

namespace {
// PT_STATS_VERBOSE=1 in the environment prints every statistical check, passed or not.
void maybe_print(const std::string& line) {
  static const bool verbose = std::getenv("PT_STATS_VERBOSE") != nullptr;
  if (verbose) std::printf("[stats] %s\n", line.c_str());
}
}  // namespace

::testing::AssertionResult check(const MeanTestResult& r) {
  maybe_print(r.describe());
  if (r.passed()) return ::testing::AssertionSuccess() << r.describe();
  return ::testing::AssertionFailure() << "mean differs from the closed form: " << r.describe();
}

::testing::AssertionResult mean_matches(const RunningStats& s, double expected, double alpha,
                                        const std::string& what) {
  return check(t_test_mean(s, expected, alpha, what));
}

// ---------------------------------------------------------------------------
// Variance ratios

VarianceRatioResult compare_variances(const RunningStats& a, const RunningStats& b) {
  VarianceRatioResult r;
  r.n_a = a.count();
  r.n_b = b.count();
  r.nonfinite = a.nonfinite_count() + b.nonfinite_count();
  r.var_a = a.variance();
  r.var_b = b.variance();
  r.kurtosis_a = a.kurtosis();
  r.kurtosis_b = b.kurtosis();
  r.ratio = r.var_b > 0.0 ? r.var_a / r.var_b : (r.var_a > 0.0 ? kInf : std::nan(""));
  // Delta method: Var(log s^2) ~ Var(s^2) / s^4. A zero variance contributes
  // nothing (a sample of constants is known exactly).
  double rel_a = r.var_a > 0.0 ? a.variance_of_variance() / (r.var_a * r.var_a) : 0.0;
  double rel_b = r.var_b > 0.0 ? b.variance_of_variance() / (r.var_b * r.var_b) : 0.0;
  r.log_ratio_se = std::sqrt(rel_a + rel_b);
  return r;
}

namespace {

// z of log(ratio) against log(hypothesis), with the degenerate cases (a
// variance of exactly zero on either side) mapped to +-infinity.
double log_ratio_z(const VarianceRatioResult& r) {
  if (std::isnan(r.ratio)) return 0.0;  // both constant: no evidence either way
  if (r.ratio == kInf) return kInf;
  if (r.ratio == 0.0) return -kInf;
  double d = std::log(r.ratio) - std::log(r.hypothesis);
  if (r.log_ratio_se <= 0.0) return d == 0.0 ? 0.0 : std::copysign(kInf, d);
  return d / r.log_ratio_se;
}

// Both variance-ratio tests: `h0` describes the hypothesis, p_of_z turns the
// statistic into its p-value.
template <class PValue>
VarianceRatioResult variance_ratio_test(const RunningStats& a, const RunningStats& b, double factor, double alpha,
                                        const std::string& h0, const PValue& p_of_z) {
  VarianceRatioResult r = compare_variances(a, b);
  r.what = h0;
  r.hypothesis = factor;
  r.alpha = alpha;
  r.statistic = log_ratio_z(r);
  r.p_value = r.nonfinite > 0 ? 0.0 : p_of_z(r.statistic);
  return r;
}

}  // namespace

VarianceRatioResult variance_ratio_at_least(const RunningStats& a, const RunningStats& b, double factor,
                                            double alpha, const std::string& what) {
  // Evidence against H0 lies in the lower tail only.
  return variance_ratio_test(a, b, factor, alpha, what + " [H0: Var(A)/Var(B) >= " + fmt(factor) + ", one-sided]",
                             [](double z) { return z >= 0.0 ? 1.0 : normal_cdf(z); });
}

VarianceRatioResult variance_at_most(const RunningStats& a, double bound, double alpha, const std::string& what) {
  VarianceRatioResult r = compare_variances(a, RunningStats());
  r.var_b = bound;
  r.ratio = a.variance() / bound;
  r.what = what + " [H0: Var(A) <= " + fmt(bound) + ", a bound known exactly, one-sided]";
  r.hypothesis = 1.0;
  r.alpha = alpha;
  r.statistic = log_ratio_z(r);
  // Evidence against H0 lies in the upper tail only.
  r.p_value = r.nonfinite > 0 ? 0.0 : (r.statistic <= 0.0 ? 1.0 : normal_sf(r.statistic));
  return r;
}

VarianceRatioResult variance_ratio_equals(const RunningStats& a, const RunningStats& b, double factor, double alpha,
                                          const std::string& what) {
  return variance_ratio_test(a, b, factor, alpha, what + " [H0: Var(A)/Var(B) = " + fmt(factor) + ", two-sided]",
                             [](double z) { return std::min(1.0, 2.0 * normal_sf(std::abs(z))); });
}

std::string VarianceRatioResult::describe() const {
  std::ostringstream os;
  os << what << ": n_A=" << n_a << " Var(A)=" << fmt(var_a) << " kurtosis(A)=" << fmt(kurtosis_a) << "; n_B=" << n_b
     << " Var(B)=" << fmt(var_b) << " kurtosis(B)=" << fmt(kurtosis_b) << "; ratio=" << fmt(ratio)
     << " se(log ratio)=" << fmt(log_ratio_se) << " z=" << fmt(statistic) << " p=" << fmt(p_value)
     << " alpha=" << fmt(alpha) << " (log variance ratio, asymptotically normal, se from the 4th moments)";
  if (nonfinite > 0) os << "; " << nonfinite << " samples were NaN or infinite";
  return os.str();
}

::testing::AssertionResult check(const VarianceRatioResult& r) {
  maybe_print(r.describe());
  if (r.passed()) return ::testing::AssertionSuccess() << r.describe();
  return ::testing::AssertionFailure() << "variance ratio rejected: " << r.describe();
}

// ---------------------------------------------------------------------------
// Chi-square

ChiSquareResult chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected, double alpha,
                                double min_expected) {
  ChiSquareResult r;
  r.alpha = alpha;
  r.cells = int(observed.size());
  r.samples = std::accumulate(observed.begin(), observed.end(), 0.0);
  // Cells the density gives no mass at all.
  for (size_t i = 0; i < observed.size(); ++i)
    if (expected[i] <= 0.0 && observed[i] > 0.0) {
      std::ostringstream os;
      os << observed[i] << " samples in cell " << i << " where the density is zero";
      r.failure = os.str();
      r.p_value = 0.0;
      return r;
    }
  // Pool the cells with small expected counts, smallest first.
  std::vector<size_t> order(observed.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  double chi2 = 0.0;
  int bins = 0;
  double pool_obs = 0.0, pool_exp = 0.0;
  int pool_size = 0;
  for (size_t k : order) {
    if (expected[k] <= 0.0) continue;  // no mass, no samples: not a cell at all
    if (expected[k] < min_expected) {
      pool_obs += observed[k];
      pool_exp += expected[k];
      ++pool_size;
      ++r.pooled_cells;
      if (pool_exp >= min_expected) {
        chi2 += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
        ++bins;
        pool_obs = pool_exp = 0.0;
        pool_size = 0;
      }
      continue;
    }
    if (pool_size > 0) {  // a remainder pool joins the first regular cell
      double o = observed[k] + pool_obs, e = expected[k] + pool_exp;
      chi2 += (o - e) * (o - e) / e;
      pool_obs = pool_exp = 0.0;
      pool_size = 0;
    } else {
      chi2 += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
    }
    ++bins;
  }
  if (pool_size > 0) {  // every cell was small: the remainder is one more bin
    chi2 += (pool_obs - pool_exp) * (pool_obs - pool_exp) / std::max(pool_exp, 1e-300);
    ++bins;
  }
  r.statistic = chi2;
  r.dof = bins - 1;
  if (r.dof < 1) {
    r.failure = "fewer than 2 cells after pooling: too few samples for a chi-square test";
    r.p_value = 0.0;
    return r;
  }
  r.p_value = chi_square_sf(chi2, r.dof);
  return r;
}

std::string ChiSquareResult::describe() const {
  std::ostringstream os;
  if (!what.empty()) os << what << ": ";
  os << "chi2=" << fmt(statistic) << " dof=" << dof << " p=" << fmt(p_value) << " alpha=" << fmt(alpha)
     << " (samples=" << samples << ", cells=" << cells << ", " << pooled_cells
     << " cells with expected count < 5 pooled)";
  if (outside > 0) os << "; " << outside << " samples fell outside the grid";
  if (!failure.empty()) os << "; " << failure;
  if (!report_dir.empty())
    os << "\n  observed and expected tables and histogram.png (observed | expected | residual) written to "
       << report_dir;
  return os.str();
}

::testing::AssertionResult check(const ChiSquareResult& r) {
  maybe_print(r.describe());
  if (r.passed()) return ::testing::AssertionSuccess() << r.describe();
  return ::testing::AssertionFailure() << "the samples do not follow the density: " << r.describe();
}

int Grid2D::cell(double x, double y) const {
  if (!(x >= x0 && x <= x1 && y >= y0 && y <= y1)) return -1;
  const int i = std::clamp(int((x - x0) / (x1 - x0) * nx), 0, nx - 1);
  const int j = std::clamp(int((y - y0) / (y1 - y0) * ny), 0, ny - 1);
  return j * nx + i;
}

namespace {

// Adaptive 2-D Simpson quadrature on a rectangle (a quadtree): v holds the
// density on a 5 x 5 grid over [x0, x1] x [y0, y1]. The 3 x 3 Simpson rule on
// the whole rectangle is compared with the sum of the rules on its four
// quarters (the same 25 values); where they differ by more than 15 eps the
// quarters are refined, each with eps / 4, down to max_depth levels.
struct Simpson2D {
  using Block = std::array<std::array<double, 5>, 5>;  // [j][i]: y index, x index
  const std::function<double(double, double)>& f;

  // Simpson's 3 x 3 rule on the sub-block whose corner is (2a, 2b) with
  // stride `step` (step 2, a = b = 0: the whole rectangle from every other
  // value; step 1: one quarter).
  static double rule(const Block& v, int a, int b, int step, double area) {
    static const double w[3] = {1.0, 4.0, 1.0};
    double s = 0.0;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) s += w[i] * w[j] * v[2 * b + step * j][2 * a + step * i];
    return s * area / 36.0;
  }

  Block sample(double x0, double x1, double y0, double y1) const {
    Block v;
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) v[j][i] = f(x0 + 0.25 * (x1 - x0) * i, y0 + 0.25 * (y1 - y0) * j);
    return v;
  }

  double integrate(double x0, double x1, double y0, double y1, const Block& v, double eps, int depth,
                   int min_depth) const {
    const double area = (x1 - x0) * (y1 - y0);
    const double whole = rule(v, 0, 0, 2, area);
    double fine = 0.0;
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) fine += rule(v, a, b, 1, 0.25 * area);
    const double delta = fine - whole;
    // The edge of the density's support (a light's outline) inside the block:
    // Simpson's error estimate means little across a jump, so refine anyway.
    bool zero = false, nonzero = false;
    for (const auto& row : v)
      for (double x : row) (x == 0.0 ? zero : nonzero) = true;
    const bool converged = min_depth <= 0 && std::abs(delta) <= 15.0 * eps && !(zero && nonzero);
    if (depth <= 0 || converged) return fine + delta / 15.0;
    double total = 0.0;
    const double hx = 0.5 * (x1 - x0), hy = 0.5 * (y1 - y0);
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) {
        const double cx0 = x0 + a * hx, cy0 = y0 + b * hy;
        Block c;
        for (int j = 0; j < 5; ++j)
          for (int i = 0; i < 5; ++i)
            c[j][i] = (i % 2 == 0 && j % 2 == 0) ? v[2 * b + j / 2][2 * a + i / 2]
                                                 : f(cx0 + 0.25 * hx * i, cy0 + 0.25 * hy * j);
        total += integrate(cx0, cx0 + hx, cy0, cy0 + hy, c, 0.25 * eps, depth - 1, min_depth - 1);
      }
    return total;
  }

  // One cell, first cut into pieces x pieces rectangles; the tolerance is
  // rel_eps times the cell's first (rough) integral of |f|.
  double cell(double x0, double x1, double y0, double y1, int pieces, double rel_eps, int max_depth) const {
    std::vector<Block> vals;
    const double hx = (x1 - x0) / pieces, hy = (y1 - y0) / pieces;
    double rough = 0.0;
    for (int pj = 0; pj < pieces; ++pj)
      for (int pi = 0; pi < pieces; ++pi) {
        vals.push_back(sample(x0 + hx * pi, x0 + hx * (pi + 1), y0 + hy * pj, y0 + hy * (pj + 1)));
        Block a = vals.back();
        for (auto& row : a)
          for (double& x : row) x = std::abs(x);
        rough += rule(a, 0, 0, 2, hx * hy);
      }
    const double eps = rel_eps * rough / (double(pieces) * pieces);
    double total = 0.0;
    for (int pj = 0; pj < pieces; ++pj)
      for (int pi = 0; pi < pieces; ++pi)
        total += integrate(x0 + hx * pi, x0 + hx * (pi + 1), y0 + hy * pj, y0 + hy * (pj + 1),
                           vals[size_t(pj) * pieces + pi], eps, max_depth, 1);
    return total;
  }
};

}  // namespace

std::vector<double> integrate_over_cells(const Grid2D& g, const std::function<double(double, double)>& density,
                                         int subdivisions, double rel_eps, int max_depth) {
  std::vector<double> out(size_t(g.nx) * g.ny, 0.0);
  const Simpson2D simpson{density};
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      out[size_t(j) * g.nx + i] = simpson.cell(g.cell_x0(i), g.cell_x0(i + 1), g.cell_y0(j), g.cell_y0(j + 1),
                                               subdivisions, rel_eps, max_depth);
  return out;
}

ChiSquare2D::ChiSquare2D(std::string what, const Grid2D& grid)
    : what_(std::move(what)), grid_(grid), observed_(size_t(grid.nx) * grid.ny, 0.0) {}

void ChiSquare2D::add(double x, double y) {
  total_ += 1.0;
  int c = grid_.cell(x, y);
  if (c < 0)
    outside_ += 1.0;
  else
    observed_[c] += 1.0;
}

std::string ChiSquare2D::report_dir() const {
  std::string test = "unknown_test";
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
    test = std::string(info->test_suite_name()) + "." + info->name();
  std::string label;
  for (char c : what_) label += (std::isalnum((unsigned char)c) || c == '-' || c == '.') ? c : '_';
  return (std::filesystem::absolute("test_output") / test / label).string();
}

ChiSquareResult ChiSquare2D::run(const std::function<double(double, double)>& density, double alpha,
                                 int subdivisions) {
  // Keep the leaves along support edges at ~1/1024 of a cell whatever the
  // first subdivision (4 pieces and 8 levels by default).
  int depth = 0;
  while (subdivisions * (1 << depth) < 1024 && depth < 12) ++depth;
  std::vector<double> expected = integrate_over_cells(grid_, density, subdivisions, 1e-6, depth);
  for (double& e : expected) e *= total_;
  ChiSquareResult r = chi_square_test(observed_, expected, alpha);
  r.what = what_;
  r.samples = total_;
  r.outside = outside_;
  if (outside_ > 0.0 && r.failure.empty()) {
    r.failure = "samples outside the domain, where the density is zero";
    r.p_value = 0.0;
  }
  static const bool always = std::getenv("PT_STATS_REPORT") != nullptr;
  if (!r.passed() || always) {
    r.report_dir = report_dir();
    try {
      write_report(expected, r);
    } catch (const std::exception& e) {
      r.report_dir += std::string(" (could not write the report: ") + e.what() + ")";
    }
  }
  return r;
}

void ChiSquare2D::write_report(const std::vector<double>& expected, const ChiSquareResult& r) const {
  namespace fs = std::filesystem;
  const fs::path dir = report_dir();
  fs::create_directories(dir);
  const int nx = grid_.nx, ny = grid_.ny;
  auto table = [&](const fs::path& file, const std::vector<double>& v, const char* title) {
    std::ofstream os(file);
    os << "# " << title << " counts of '" << what_ << "': " << ny << " rows (" << y_label << " from " << grid_.y1
       << " at the top down to " << grid_.y0 << ") x " << nx << " columns (" << x_label << " from " << grid_.x0
       << " to " << grid_.x1 << ")\n";
    os << std::fixed << std::setprecision(1);
    for (int j = ny - 1; j >= 0; --j) {
      for (int i = 0; i < nx; ++i) os << (i ? " " : "") << v[size_t(j) * nx + i];
      os << "\n";
    }
  };
  table(dir / "observed.txt", observed_, "observed");
  table(dir / "expected.txt", expected, "expected");
  std::ofstream(dir / "summary.txt") << r.describe() << "\n";

  // observed | expected | residual, each cell a block of pixels.
  const int scale = std::max(1, 300 / std::max(nx, ny));
  const int gap = 4, pw = nx * scale, ph = ny * scale;
  Image img(3 * pw + 2 * gap, ph, Spectrum(0.1, 0.1, 0.3));
  double vmax = 1e-300;
  for (size_t k = 0; k < observed_.size(); ++k) vmax = std::max({vmax, observed_[k], expected[k]});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const size_t k = size_t(j) * nx + i;
      const double o = observed_[k] / vmax, e = expected[k] / vmax;
      const double res = expected[k] > 0.0 ? (observed_[k] - expected[k]) / std::sqrt(expected[k])
                                           : (observed_[k] > 0.0 ? 10.0 : 0.0);
      const double a = std::min(1.0, std::abs(res) / 5.0);  // 5 standard deviations saturate
      const Spectrum rc = res > 0 ? Spectrum(a, 0.0, 0.0) : Spectrum(0.0, 0.0, a);
      for (int dy = 0; dy < scale; ++dy)
        for (int dx = 0; dx < scale; ++dx) {
          const int y = (ny - 1 - j) * scale + dy, x = i * scale + dx;
          img.at(x, y) = Spectrum(o);
          img.at(pw + gap + x, y) = Spectrum(e);
          img.at(2 * (pw + gap) + x, y) = rc;
        }
    }
  write_png((dir / "histogram.png").string(), img);
}

DirectionalChiSquare::DirectionalChiSquare(std::string what, const Vec3& axis, int n_cos, int n_phi, double cos_min,
                                           double cos_max)
    : frame_(Frame::from_normal(glm::normalize(axis))),
      hist_(std::move(what), Grid2D{n_phi, n_cos, 0.0, 2.0 * kPi, cos_min, cos_max}) {
  hist_.x_label = "phi";
  hist_.y_label = "cos theta";
}

void DirectionalChiSquare::add(const Vec3& w) {
  const Vec3 l = frame_.to_local(glm::normalize(w));
  double phi = std::atan2(l.y, l.x);
  if (phi < 0.0) phi += 2.0 * kPi;
  if (phi >= 2.0 * kPi) phi = 0.0;
  hist_.add(phi, std::clamp(l.z, -1.0, 1.0));
}

Vec3 DirectionalChiSquare::direction(double cos_theta, double phi) const {
  const double c = std::clamp(cos_theta, -1.0, 1.0), s = std::sqrt(std::max(0.0, 1.0 - c * c));
  return frame_.to_world(Vec3(s * std::cos(phi), s * std::sin(phi), c));
}

ChiSquareResult DirectionalChiSquare::run(const std::function<double(const Vec3&)>& pdf_solid_angle, double alpha,
                                          int subdivisions) {
  return hist_.run([&](double phi, double c) { return pdf_solid_angle(direction(c, phi)); }, alpha, subdivisions);
}

}  // namespace pt::stats
