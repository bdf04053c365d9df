// The error model (support/error_model.h) on synthetic images whose per-pixel
// distributions are known, so that its constants can be checked against
// closed forms and its predictions against simulation, with no renderer.
//
// Pixel p's samples are 3-vectors: red ~ an exponential of mean m_p, green a
// copy of red (fully correlated channels), blue ~ a rare event (1/q with
// probability q, else 0, mean 1, heavy tailed). Closed forms per sample:
//   exponential(mean m): variance m^2, fourth cumulant 6 m^4;
//   rare event: variance 1/q - 1, fourth cumulant 1/q^3 - 7/q^2 + 12/q - 6
//     (a Bernoulli's q (1 - q) (1 - 6 q (1 - q)), scaled by 1/q^4);
//   red and green: covariance m^2, joint cumulant k(r,r,g,g) = 6 m^4;
//   blue with red or green: independent, 0.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "support/error_model.h"
#include "support/seed.h"
#include "support/statistics.h"

namespace pt::error_model {
namespace {

constexpr int kW = 40, kH = 25;  // 1000 pixels
constexpr double kRare = 0.02;   // q

double pixel_mean(int i) { return 0.2 + 0.8 * (i % 17) / 16.0; }

struct Synthetic {
  Rng rng;
  explicit Synthetic(uint64_t seed) : rng(seed) {}
  Spectrum sample(int i) {
    double r = -pixel_mean(i) * std::log(1.0 - rng.uniform());
    double b = rng.uniform() < kRare ? 1.0 / kRare : 0.0;
    return Spectrum(r, r, b);
  }
  Image render(int spp) {
    Image img(kW, kH);
    for (int i = 0; i < kW * kH; ++i) {
      Spectrum s(0.0);
      for (int k = 0; k < spp; ++k) s += sample(i);
      img.pixels[i] = s / double(spp);
    }
    return img;
  }
};

// a, c2 and c3 of the closed forms, with the weights of `ref`.
RelMSEModel closed_form(const Image& ref, int reference_samples) {
  RelMSEModel m;
  m.reference_samples = reference_samples;
  const double q = kRare, var_b = 1.0 / q - 1.0, k4_b = 1.0 / (q * q * q) - 7.0 / (q * q) + 12.0 / q - 6.0;
  for (int i = 0; i < kW * kH; ++i) {
    const double mu = pixel_mean(i), var_r = mu * mu, k4_r = 6.0 * mu * mu * mu * mu;
    double w[3];
    for (int c = 0; c < 3; ++c) w[c] = 1.0 / (ref.pixels[i][c] * ref.pixels[i][c] + kRelMSEEpsilon);
    m.a += (w[0] + w[1]) * var_r + w[2] * var_b;
    // (c, d) over {r, g}^2 all have covariance var_r and cumulant k4_r; (b, b) its own.
    const double wrg = w[0] + w[1];
    m.c2 += 2.0 * (wrg * wrg * var_r * var_r + w[2] * w[2] * var_b * var_b);
    m.c3 += wrg * wrg * k4_r + w[2] * w[2] * k4_b;
  }
  const double terms = 3.0 * kW * kH;
  m.a /= terms, m.c2 /= terms * terms, m.c3 /= terms * terms;
  return m;
}

// 4000 passes of 4 samples per pixel. The estimated constants average
// per-pixel moment estimates over 1000 pixels; the slowest to converge is the
// blue channel's fourth cumulant, whose per-pixel estimate from 4000 passes
// has a relative standard error of about sqrt(E[x^8] / 4000) / k4 = 0.7 at
// pass level, 2% after averaging 1000 pixels. The 10% tolerance is five of
// those: only a wrong formula (a missing factor n0^3, a cross term, a wrong
// sign) is off by more, and those are off by tens of percent or more.
TEST(ErrorModel, PassMomentsRecoverTheClosedForms) {
  constexpr int kPasses = 4000, kPassSamples = 4;
  Synthetic gen(test::seed(11));
  PassMoments moments(kW, kH, kPassSamples);
  for (int k = 0; k < kPasses; ++k) moments.add(gen.render(kPassSamples));
  const Image ref = moments.mean();
  const RelMSEModel got = moments.model(ref), want = closed_form(ref, kPasses * kPassSamples);
  EXPECT_EQ(got.reference_samples, kPasses * kPassSamples);
  EXPECT_NEAR(got.a, want.a, 0.10 * want.a) << "a: relative variance of one sample";
  EXPECT_NEAR(got.c2, want.c2, 0.10 * want.c2) << "c2: the Gaussian part of Var[relMSE]";
  EXPECT_NEAR(got.c3, want.c3, 0.10 * want.c3) << "c3: the fourth-cumulant part of Var[relMSE]";
  // The per-sample standard deviation image: red sqrt(var_r) = m, blue sqrt(1/q - 1).
  const Image sd = moments.sample_sd();
  for (int i : {0, 16, 500}) {
    EXPECT_NEAR(sd.pixels[i][0], pixel_mean(i), 0.10 * pixel_mean(i)) << "pixel " << i;
    EXPECT_NEAR(sd.pixels[i][2], std::sqrt(1.0 / kRare - 1.0), 0.15 * std::sqrt(1.0 / kRare - 1.0)) << "pixel " << i;
  }
}

// The model's prediction against simulation: 400 independent 16-spp renders
// compared with the reference (from independent samples, as in the library).
// Their mean relMSE must match E[S] (t test, alpha 1e-5; the model's own
// estimation error, from 8000 passes, is a third of the test's standard
// error and widens it by 6%), and their spread sd[S] within 20% (the sample
// sd of 400 values has a relative standard error near 1/sqrt(2 * 400) = 3.5%
// for a normal S, somewhat more with the slight skew of S here: 20% is over
// five of them). The heavy-tailed blue channel makes c3 matter: without it
// the predicted sd[S] is 35% too small here. With the weights' correlation
// to the variance estimate left uncorrected (PassMoments::model), E[S] was
// 1.6-1.9% too small with 2000 passes (4-5 standard errors; the bias falls as
// 1 / passes).
TEST(ErrorModel, PredictsTheMeanAndSpreadOfRelMSE) {
  constexpr int kPasses = 8000, kPassSamples = 4, kRenders = 400, kSpp = 16;
  Synthetic gen(test::seed(12));
  PassMoments moments(kW, kH, kPassSamples);
  for (int k = 0; k < kPasses; ++k) moments.add(gen.render(kPassSamples));
  const Image ref = moments.mean();
  const RelMSEModel model = moments.model(ref);
  stats::RunningStats relmse;
  for (int k = 0; k < kRenders; ++k) relmse.add(compare_images(gen.render(kSpp), ref).relmse);
  EXPECT_TRUE(stats::mean_matches(relmse, model.expected(kSpp), 1e-5, "relMSE at 16 spp"))
      << "model: " << model.expected(kSpp) << " +- " << model.sd(kSpp);
  EXPECT_NEAR(relmse.std_dev(), model.sd(kSpp), 0.20 * model.sd(kSpp)) << "spread of relMSE at 16 spp";
  const double without_c3 = std::sqrt(model.c2) * (1.0 / kSpp + 1.0 / model.reference_samples);
  EXPECT_LT(without_c3, 0.75 * relmse.std_dev()) << "the heavy tail should matter in this test";
}

TEST(ErrorModel, ReferenceShareAndBound) {
  RelMSEModel m;
  m.a = 2.0, m.c2 = 1e-4, m.c3 = 1e-3, m.reference_samples = 1000;
  EXPECT_DOUBLE_EQ(m.expected(10), 2.0 * (0.1 + 0.001));
  EXPECT_DOUBLE_EQ(m.sd(10), std::sqrt(1e-4 * 0.101 * 0.101 + 1e-3 / 1000.0));
  EXPECT_DOUBLE_EQ(m.bound(10, 3.0), m.expected(10) + 3.0 * m.sd(10));
  EXPECT_DOUBLE_EQ(m.reference_share(10), 10.0 / 1010.0);
}

}  // namespace
}  // namespace pt::error_model
