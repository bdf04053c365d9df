// Budgeted adaptive sampling (render/budget.h): the allocation's closed
// forms, the pooled noise estimate leaving the pixel itself out, determinism
// across threads, and the absence of the stopping rule's self-selection bias.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/budget.h"
#include "render/limits.h"
#include "support/scene_builders.h"
#include "support/statistics.h"

namespace pt {
namespace {

long long sum(const std::vector<int>& v) { return std::accumulate(v.begin(), v.end(), 0LL); }

// n ∝ r exactly when every share is an integer above the floor.
TEST(BudgetAllocation, CountsProportionalToRelativeSd) {
  EXPECT_EQ(allocate_counts({1, 2, 3, 4}, 100, 1, 1000), (std::vector<int>{10, 20, 30, 40}));
}

// The floor binds for r = 0; the rest is shared 1 : 3 (lambda = 2).
TEST(BudgetAllocation, FloorThenProportional) {
  EXPECT_EQ(allocate_counts({0, 1, 3}, 10, 2, 1000), (std::vector<int>{2, 2, 6}));
}

// Equal shares of 10 over 3: the one left over goes to the lowest index.
TEST(BudgetAllocation, RemainderToLowestIndexOnTies) {
  EXPECT_EQ(allocate_counts({1, 1, 1}, 10, 1, 1000), (std::vector<int>{4, 3, 3}));
}

// No usable noise estimate anywhere (all 0, NaN, infinite): equal shares.
TEST(BudgetAllocation, NoEstimateSharesEqually) {
  const double nan = std::nan("");
  EXPECT_EQ(allocate_counts({0, nan, 0, INFINITY}, 16, 2, 1000), (std::vector<int>{4, 4, 4, 4}));
}

// The cap binds for the noisiest pixel; the other 15 go to the others 1 : 2.
TEST(BudgetAllocation, CapThenProportional) {
  EXPECT_EQ(allocate_counts({1, 2, 100}, 40, 1, 25), (std::vector<int>{5, 10, 25}));
}

// Irrational shares still sum exactly to the budget, each within one of its
// real-valued share (n_i = 1000 r_i / sum r).
// A round's floors are the counts so far: lambda = 5 spends 30 over floors
// 2, 20, 2 (the middle pixel keeps its 20); with no estimate, what is left
// over the floors is shared equally.
TEST(BudgetAllocation, FloorsPerPixel) {
  EXPECT_EQ(allocate_counts({1, 1, 1}, 30, std::vector<int>{2, 20, 2}, 1000), (std::vector<int>{5, 20, 5}));
  EXPECT_EQ(allocate_counts({0, 0}, 10, std::vector<int>{1, 5}, 100), (std::vector<int>{3, 7}));
  EXPECT_EQ(allocate_counts({1, 3}, 10, std::vector<int>{1, 1}, 100), allocate_counts({1, 3}, 10, 1, 100))
      << "equal floors: the same as one floor for all";
}

TEST(BudgetAllocation, SumsExactlyToTheBudget) {
  std::vector<double> r;
  for (int i = 1; i <= 97; ++i) r.push_back(std::sqrt(double(i)));
  const std::vector<int> n = allocate_counts(r, 1000 * 97LL, 1, 1 << 20);
  EXPECT_EQ(sum(n), 97000);
  const double rsum = std::accumulate(r.begin(), r.end(), 0.0);
  for (size_t i = 0; i < r.size(); ++i) EXPECT_NEAR(n[i], 97000 * r[i] / rsum, 1.0) << "pixel " << i;
}

PixelSums pixel(std::vector<Spectrum> samples) {
  PixelSums p;
  for (const Spectrum& s : samples) p.sum += s, p.sum_sq += s * s, ++p.n;
  return p;
}

// 3 x 3 pixels, constant 1 except the centre (samples 0 and 2: mean 1,
// variance 2). The centre's own noise must not enter its estimate (that would
// tie its count to its own values): every line through it is constant, so
// r = 0. A corner and an edge pixel each have one line through the centre
// whose other end is outside the image: variance 2 / (1 + eps), the largest
// of their lines.
TEST(BudgetPooling, LeavesThePixelItselfOut) {
  std::vector<PixelSums> pilot(9, pixel({Spectrum(1.0), Spectrum(1.0)}));
  pilot[4] = pixel({Spectrum(0.0), Spectrum(2.0)});
  const std::vector<double> r = pooled_relative_sd(pilot, 3, 3);
  EXPECT_EQ(r[4], 0.0);
  EXPECT_NEAR(r[0], std::sqrt(2.0 / 1.01), 1e-12);
  EXPECT_NEAR(r[1], std::sqrt(2.0 / 1.01), 1e-12);
}

// A line whose two ends are both noisy outweighs one with a single noisy end:
// a row of noisy pixels (an edge) sees itself in full. 3 x 3, the middle row
// noisy (samples 0 and 2), the rest constant 1. The middle row's centre: its
// horizontal line pools two noisy neighbours, 2 x 2 / (2 x 1 + 2 eps). The
// top row's centre: at best one noisy end, 2 / (1 + eps) (its vertical line
// reaches outside the image).
TEST(BudgetPooling, AnEdgeSeesItselfAlongItsLine) {
  std::vector<PixelSums> pilot(9, pixel({Spectrum(1.0), Spectrum(1.0)}));
  for (int i = 3; i < 6; ++i) pilot[i] = pixel({Spectrum(0.0), Spectrum(2.0)});
  const std::vector<double> r = pooled_relative_sd(pilot, 3, 3);
  EXPECT_NEAR(r[4], std::sqrt(4.0 / 2.02), 1e-12);
  EXPECT_NEAR(r[1], std::sqrt(2.0 / 1.01), 1e-12);
}

// A pixel with a NaN sample is left out of its neighbours' pools, not spread
// around. Finite pixels: samples 1 and 3 (mean 2, variance 2); pixel 0's
// diagonal line ends at the NaN pixel and outside the image, so it has none.
TEST(BudgetPooling, SkipsNonFinitePixels) {
  std::vector<PixelSums> pilot(4, pixel({Spectrum(1.0), Spectrum(3.0)}));
  pilot[3] = pixel({Spectrum(std::nan("")), Spectrum(1.0)});
  pilot[3].finite = false;
  const std::vector<double> r = pooled_relative_sd(pilot, 2, 2);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r[i], std::sqrt(2 / 4.01), 1e-12) << "pixel " << i;
}

RenderSettings budget_settings(int budget) {
  RenderSettings s;
  s.width = 24;
  s.height = 20;  // partial tiles
  s.ns_area_light = 1;
  s.max_ray_depth = 3;
  s.seed = 11;
  s.adaptive_budget = budget;
  return s;
}

TEST(BudgetRender, SameImageAndCountsWithOneAndTwoThreads) {
  Scene scene = test::make_cornell_box();
  PathTracer tracer(scene, budget_settings(16));
  RenderResult one = render(tracer, 1), two = render(tracer, 2);
  ASSERT_TRUE(one.ok()) << one.error;
  ASSERT_TRUE(two.ok()) << two.error;
  EXPECT_EQ(one.sample_counts, two.sample_counts);
  for (size_t i = 0; i < one.image.pixels.size(); ++i) ASSERT_EQ(one.image.pixels[i], two.image.pixels[i]) << "pixel " << i;
  EXPECT_EQ(one.work.rays, two.work.rays);
}

// The budget is spent exactly, every pixel keeps its pilot, and the counts
// are not all equal in a scene with both noisy and noise-free regions.
TEST(BudgetRender, SpendsTheBudgetExactly) {
  Scene scene = test::make_cornell_box();
  RenderSettings s = budget_settings(16);
  RenderResult r = render(PathTracer(scene, s), 2);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(sum(r.sample_counts), 16LL * s.width * s.height);
  EXPECT_GE(*std::min_element(r.sample_counts.begin(), r.sample_counts.end()), pilot_samples(16));
  EXPECT_GT(*std::max_element(r.sample_counts.begin(), r.sample_counts.end()), 16);
}

// Rounds: still exactly the budget, never below the pilot, the same image on
// any number of threads; and another image than one round's (r re-estimated).
TEST(BudgetRender, RoundsSpendTheBudgetExactlyOnAnyThreads) {
  Scene scene = test::make_cornell_box();
  RenderSettings s = budget_settings(16);
  s.adaptive_rounds = 3;
  RenderResult one = render(PathTracer(scene, s), 1), two = render(PathTracer(scene, s), 2);
  ASSERT_TRUE(one.ok()) << one.error;
  ASSERT_TRUE(two.ok()) << two.error;
  EXPECT_EQ(sum(two.sample_counts), 16LL * s.width * s.height);
  EXPECT_GE(*std::min_element(two.sample_counts.begin(), two.sample_counts.end()), pilot_samples(16));
  EXPECT_EQ(one.sample_counts, two.sample_counts);
  for (size_t i = 0; i < one.image.pixels.size(); ++i) ASSERT_EQ(one.image.pixels[i], two.image.pixels[i]) << "pixel " << i;
  s.adaptive_rounds = 1;
  RenderResult single = render(PathTracer(scene, s), 2);
  ASSERT_TRUE(single.ok()) << single.error;
  EXPECT_NE(single.sample_counts, two.sample_counts) << "three rounds allocated as one: r was not re-estimated";
}

TEST(BudgetRender, RefusesABadBudgetOrBothSamplers) {
  Scene scene = test::make_cornell_box();
  for (int bad : {1, -3, kMaxSamples + 1}) {
    RenderResult r = render(PathTracer(scene, budget_settings(bad)), 1);
    EXPECT_NE(r.error.find("adaptive budget"), std::string::npos) << bad << ": " << r.error;
  }
  RenderSettings both = budget_settings(8);
  both.adaptive = true;
  RenderResult r = render(PathTracer(scene, both), 1);
  EXPECT_NE(r.error.find("choose one"), std::string::npos) << r.error;
  for (int bad : {0, kMaxAdaptiveRounds + 1}) {
    RenderSettings rounds = budget_settings(8);
    rounds.adaptive_rounds = bad;
    RenderResult e = render(PathTracer(scene, rounds), 1);
    EXPECT_NE(e.error.find("adaptive rounds"), std::string::npos) << bad << ": " << e.error;
  }
}

// A radiance estimate with a known distribution: mean 1 in every pixel, the
// left half Bernoulli(1/2) x 2 (variance 1), the right half Bernoulli(1/4) x 4
// (variance 3), drawn from the pixel's own generator.
class TwoNoiseTracer : public PathTracer {
 public:
  using PathTracer::PathTracer;
  Spectrum est_radiance_global_illumination(const Ray& r, Rng& rng) const override {
    const bool right = r.d.x > 0;  // the camera looks down -z: x > 0 is the image's right half
    return Spectrum(right ? (rng.uniform() < 0.25 ? 4.0 : 0.0) : (rng.uniform() < 0.5 ? 2.0 : 0.0));
  }
  static double variance(bool right) { return right ? 3.0 : 1.0; }
};

struct Bias {
  double z = 0, mean_left = 0, mean_right = 0, counts_left = 0, counts_right = 0;
};

// The image's mean against 1, as a z score with the variance known from the
// distribution and the counts: sum over pixels of variance / count, over P^2.
Bias image_bias(const RenderResult& r, int width) {
  Bias b;
  double mean = 0, var = 0;
  const size_t p = r.image.pixels.size();
  int left = 0, right = 0;
  for (size_t i = 0; i < p; ++i) {
    const bool is_right = int(i % width) >= width / 2;
    mean += r.image.pixels[i].x / p;
    var += TwoNoiseTracer::variance(is_right) / r.sample_counts[i] / (double(p) * p);
    (is_right ? b.mean_right : b.mean_left) += r.image.pixels[i].x;
    (is_right ? b.counts_right : b.counts_left) += r.sample_counts[i];
    ++(is_right ? right : left);
  }
  b.mean_left /= left, b.mean_right /= right, b.counts_left /= left, b.counts_right /= right;
  b.z = (mean - 1.0) / std::sqrt(var);
  return b;
}

// Unbiased (one round): every pixel's count comes from its neighbours' pilot samples, so
// the mean of its own samples stays unbiased. Two-sided z test at alpha =
// 1e-5 (|z| < 4.42); 96 x 64 pixels at 64 samples each give the image mean a
// standard error of about 0.2%. The same statistic on the course's stopping rule
// (-a 4 0.05, which stops a pixel on four zeros, mu = 0) must see its bias:
// the control that the test can fail.
TEST(BudgetRender, UnbiasedWhereTheStoppingRuleIsNot) {
  Scene scene = test::make_cornell_box();
  RenderSettings s = budget_settings(64);  // a pilot of 8: 16 samples per line of neighbours
  s.width = 96, s.height = 64;
  s.adaptive_rounds = 1;  // the exactly unbiased allocation; rounds below
  const double z_crit = 4.42;  // normal_quantile(1 - 1e-5 / 2)
  EXPECT_NEAR(stats::normal_quantile(1 - 0.5e-5), z_crit, 0.01);
  RenderResult budget = render(TwoNoiseTracer(scene, s), 2);
  ASSERT_TRUE(budget.ok()) << budget.error;
  const Bias b = image_bias(budget, s.width);
  EXPECT_LT(std::abs(b.z), z_crit) << "image mean off by " << b.z << " standard errors (left " << b.mean_left
                                   << ", right " << b.mean_right << ")";
  // The right half is sqrt(3) times as noisy: it gets more samples (loosely:
  // the pilot's pooled estimate is noisy, the largest of four lines favours
  // the noisier estimate, and the halves' border is blurred).
  EXPECT_GT(b.counts_right, 1.3 * b.counts_left) << "left " << b.counts_left << ", right " << b.counts_right;

  // Four rounds: a pixel's earlier values reach its later counts at second
  // order (budget.h). The same test bounds that bias by what this image can
  // see (4.42 standard errors of 0.2%).
  RenderSettings four = s;
  four.adaptive_rounds = 4;
  RenderResult rounds = render(TwoNoiseTracer(scene, four), 2);
  ASSERT_TRUE(rounds.ok()) << rounds.error;
  const Bias br = image_bias(rounds, s.width);
  EXPECT_LT(std::abs(br.z), z_crit) << "four rounds: image mean off by " << br.z << " standard errors (left "
                                    << br.mean_left << ", right " << br.mean_right << ")";

  RenderSettings rule = s;
  rule.adaptive_budget = 0;
  rule.adaptive = true;
  rule.ns_aa = 64;
  rule.samples_per_batch = 4;
  rule.max_tolerance = 0.05;
  RenderResult course = render(TwoNoiseTracer(scene, rule), 2);
  ASSERT_TRUE(course.ok()) << course.error;
  EXPECT_GT(std::abs(image_bias(course, s.width).z), z_crit) << "the control: the stopping rule's bias is not seen";
}

}  // namespace
}  // namespace pt
