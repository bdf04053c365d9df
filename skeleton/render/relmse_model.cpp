#include "render/relmse_model.h"

#include <algorithm>
#include <cmath>

namespace pt::error_model {

double RelMSEModel::expected(double n) const { return a * (1.0 / n + 1.0 / reference_samples); }

double RelMSEModel::sd(double n) const {
  const double m = 1.0 / n + 1.0 / reference_samples;
  // An estimated c3 may be slightly negative (light-tailed pixels: the jitter
  // over an edge is a two-point distribution); the variance itself is not.
  return std::sqrt(std::max(0.0, c2 * m * m + c3 / (n * n * n)));
}

double RelMSEModel::reference_share(double n) const { return n / (n + reference_samples); }

}  // namespace pt::error_model
