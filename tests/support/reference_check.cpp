#include "support/reference_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "support/statistics.h"

namespace pt::library {

namespace {

constexpr const char* kChannel[3] = {"red", "green", "blue"};
// Relative rounding allowed per pixel: 16 times float's 2^-24.
constexpr double kRounding = 1e-6;

RegionDifference region_z(const Image& t, const ReferenceImage& ref, double spp, int x0, int y0, int x1, int y1,
                          int c) {
  const double per_sample = 1.0 / spp + 1.0 / ref.model.reference_samples;
  double diff = 0.0, var = 0.0, rounding = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const double r = ref.mean.at(x, y)[c], sd = ref.sd.at(x, y)[c];
      diff += t.at(x, y)[c] - r;
      var += sd * sd * per_sample;
      rounding += kRounding * std::abs(r) + 1e-12;
    }
  RegionDifference d;
  d.x0 = x0, d.y0 = y0, d.x1 = x1, d.y1 = y1, d.channel = c;
  d.mean_difference = diff / (double(x1 - x0) * (y1 - y0));
  // The stored mean is rounded to float: in a noise-free region every pixel
  // is off by the same rounding, which adds up linearly, not as noise. So
  // deviations up to the summed rounding allowance count as zero.
  const double excess = std::max(0.0, std::abs(diff) - rounding);
  d.z = excess == 0.0 ? 0.0 : std::copysign(var > 0.0 ? excess / std::sqrt(var) : kInf, diff);
  return d;
}

}  // namespace

std::string RegionDifference::describe() const {
  std::ostringstream s;
  s.precision(4);
  s << kChannel[channel] << " over x " << x0 << "-" << x1 - 1 << ", y " << y0 << "-" << y1 - 1
    << ": mean difference " << mean_difference << " (z = " << z
    << (std::isinf(z) ? ": the reference has no noise there, so any difference is real)" : ")");
  return s.str();
}

const RegionDifference& ReferenceCheck::worst() const {
  return *std::max_element(regions.begin(), regions.end(),
                           [](const auto& a, const auto& b) { return std::abs(a.z) < std::abs(b.z); });
}

ReferenceCheck check_render(const Image& test, int spp, const ReferenceImage& ref, double alpha, int grid_x,
                            int grid_y) {
  if (test.width != ref.mean.width || test.height != ref.mean.height)
    throw std::invalid_argument("check_render: the render is " + std::to_string(test.width) + "x" +
                                std::to_string(test.height) + ", the reference " + ref.name + " " +
                                std::to_string(ref.mean.width) + "x" + std::to_string(ref.mean.height));
  ReferenceCheck c;
  c.name = ref.name;
  c.samples = spp;
  c.alpha = alpha;
  for (const Spectrum& p : test.pixels) c.nonfinite += !is_finite(p);
  const int checks = 1 + 3 * (1 + grid_x * grid_y);
  const double alpha_each = stats::sidak_alpha(alpha, checks);
  c.z_relmse = stats::normal_quantile(1.0 - alpha_each);
  c.z_region = stats::normal_quantile(1.0 - alpha_each / 2.0);
  c.relmse = compare_images(test, ref.mean).relmse;
  c.expected = ref.model.expected(spp);
  c.sd = ref.model.sd(spp);
  // Plus kRounding^2, the relative rounding allowed per pixel, so that a
  // scene with no noise at all has a bound above 0.
  c.bound = ref.model.bound(spp, c.z_relmse) + kRounding * kRounding;
  const int w = test.width, h = test.height;
  for (int ch = 0; ch < 3; ++ch) c.regions.push_back(region_z(test, ref, spp, 0, 0, w, h, ch));
  for (int gy = 0; gy < grid_y; ++gy)
    for (int gx = 0; gx < grid_x; ++gx)
      for (int ch = 0; ch < 3; ++ch)
        c.regions.push_back(region_z(test, ref, spp, gx * w / grid_x, gy * h / grid_y, (gx + 1) * w / grid_x,
                                     (gy + 1) * h / grid_y, ch));
  return c;
}

std::string ReferenceCheck::describe() const {
  std::ostringstream s;
  s.precision(4);
  s << name << " at " << samples << " spp: relMSE " << relmse << ", expected " << expected << " (sd " << sd
    << "), bound " << bound << " (z = " << z_relmse << ")" << (relmse_ok() ? "" : " EXCEEDED: beyond what " +
                                                                                   std::to_string(samples) +
                                                                                   " spp explains")
    << "; worst region " << worst().describe() << ", bound |z| <= " << z_region
    << (regions_ok() ? "" : " EXCEEDED: a mean difference beyond what " + std::to_string(samples) + " spp explains");
  if (nonfinite) s << "; " << nonfinite << " NaN or infinite pixels";
  s << " [alpha " << alpha << ", Sidak over " << regions.size() + 1 << " checks]";
  return s.str();
}

::testing::AssertionResult check(const ReferenceCheck& c) {
  // As every check of the statistics toolkit: PT_STATS_VERBOSE=1 prints it, passed or not.
  static const bool verbose = std::getenv("PT_STATS_VERBOSE") != nullptr;
  if (verbose) std::printf("[stats] %s\n", c.describe().c_str());
  if (c.passed()) return ::testing::AssertionSuccess() << c.describe();
  return ::testing::AssertionFailure() << c.describe();
}

}  // namespace pt::library
