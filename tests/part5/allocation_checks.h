#pragma once
// Checks of allocate_samples (P5T3) against the water-filling solution,
// computed here by bisection on lambda: a different method from a sort-based
// solution, so that the two agree only when both are right.
//
// The spec (render/pathtracer.h): r = sqrt(variance / (mean^2 + 1e-2)), 0 for
// a pilot that is not finite or a negative variance; targets t = max(1,
// lambda r) with sum t = budget (equal shares when every r is 0); whole
// counts within 1 of their targets summing to exactly the budget. A count
// within 1 of its target is what any rounding gives, so the checks accept
// every rounding rule and pin the allocation itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "render/pathtracer.h"

namespace pt::test::part5 {

inline double relative_sd(const PilotMoments& p) {
  if (!std::isfinite(p.mean) || !std::isfinite(p.variance) || p.variance <= 0) return 0.0;
  return std::sqrt(p.variance) / std::sqrt(p.mean * p.mean + 1e-2);
}

// The targets max(1, lambda r) for budget >= pilot.size().
inline std::vector<double> water_filled_targets(const std::vector<PilotMoments>& pilot, long long budget) {
  std::vector<double> r;
  double rmax = 0;
  for (const PilotMoments& p : pilot) r.push_back(relative_sd(p)), rmax = std::max(rmax, r.back());
  const size_t n = r.size();
  if (rmax == 0) return std::vector<double>(n, double(budget) / double(n));
  auto spent = [&](double lambda) {
    double s = 0;
    for (double ri : r) s += std::max(1.0, lambda * ri);
    return s;
  };
  double lo = 0, hi = double(budget) / rmax;  // spent(hi) >= budget: the noisiest pixel alone takes it
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (spent(mid) < double(budget) ? lo : hi) = mid;
  }
  std::vector<double> t(n);
  for (size_t i = 0; i < n; ++i) t[i] = std::max(1.0, hi * r[i]);
  return t;
}

inline std::string describe(const std::vector<PilotMoments>& pilot, long long budget, size_t at_most = 8) {
  std::ostringstream os;
  os << "budget " << budget << ", " << pilot.size() << " pixels (mean, variance):";
  for (size_t i = 0; i < pilot.size() && i < at_most; ++i)
    os << " (" << pilot[i].mean << ", " << pilot[i].variance << ")";
  if (pilot.size() > at_most) os << " ...";
  return os.str();
}

// Whole counts, summing to the budget, each within 1 of its target.
inline ::testing::AssertionResult follows_water_filling(const std::vector<PilotMoments>& pilot, long long budget,
                                                        const std::vector<int>& counts) {
  const std::string inputs = describe(pilot, budget);
  if (counts.size() != pilot.size())
    return ::testing::AssertionFailure() << inputs << ": " << counts.size() << " counts for " << pilot.size()
                                         << " pixels";
  long long sum = 0;
  for (int c : counts) sum += c;
  if (sum != budget)
    return ::testing::AssertionFailure() << inputs << ": the counts sum to " << sum
                                         << "; they must spend exactly the budget";
  const std::vector<double> t = water_filled_targets(pilot, budget);
  for (size_t i = 0; i < counts.size(); ++i)
    if (counts[i] < 1 || std::abs(counts[i] - t[i]) >= 1.0 + 1e-9)
      return ::testing::AssertionFailure()
             << inputs << ": pixel " << i << " (mean " << pilot[i].mean << ", variance " << pilot[i].variance
             << ", r = " << relative_sd(pilot[i]) << ") got " << counts[i] << " samples; max(1, lambda r) is "
             << t[i] << " (each pixel at least 1, the rest in proportion to r = sqrt(variance / (mean^2 + 1e-2)))";
  return ::testing::AssertionSuccess();
}

}  // namespace pt::test::part5
