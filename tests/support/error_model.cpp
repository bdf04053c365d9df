#include "support/error_model.h"

#include <cmath>
#include <stdexcept>

namespace pt::error_model {

PassMoments::PassMoments(int width, int height, int pass_samples)
    : w_(width), h_(height), n0_(pass_samples), shift_(size_t(width) * height), sums_(size_t(width) * height, Sums{}) {}

void PassMoments::add(const Image& pass) {
  if (pass.width != w_ || pass.height != h_) throw std::invalid_argument("PassMoments::add: image size differs");
  if (k_ == 0) shift_ = pass.pixels;
  for (size_t i = 0; i < sums_.size(); ++i) {
    const Spectrum x = pass.pixels[i] - shift_[i];
    Sums& s = sums_[i];
    for (int c = 0; c < 3; ++c) {
      s.s1[c] += x[c];
      for (int d = 0; d < 3; ++d) {
        s.s2[c][d] += x[c] * x[d];
        s.s3[c][d] += x[c] * x[c] * x[d];
        s.s4[c][d] += x[c] * x[c] * x[d] * x[d];
      }
    }
  }
  ++k_;
}

Image PassMoments::mean() const {
  Image img(w_, h_);
  for (size_t i = 0; i < sums_.size(); ++i)
    for (int c = 0; c < 3; ++c) img.pixels[i][c] = shift_[i][c] + sums_[i].s1[c] / k_;
  return img;
}

void PassMoments::pixel_cumulants(size_t i, double cov[3][3], double k22[3][3]) const {
  const Sums& s = sums_[i];
  const double K = k_;
  double m[3];
  for (int c = 0; c < 3; ++c) m[c] = s.s1[c] / K;
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 3; ++d) {
      const double exy = s.s2[c][d] / K, m2 = exy - m[c] * m[d];
      cov[c][d] = m2 * K / (K - 1.0);  // unbiased
      // Central E[(x_c - m_c)^2 (x_d - m_d)^2] from the raw moments.
      const double mu22 = s.s4[c][d] / K - 2.0 * m[d] * s.s3[c][d] / K - 2.0 * m[c] * s.s3[d][c] / K +
                          m[d] * m[d] * s.s2[c][c] / K + m[c] * m[c] * s.s2[d][d] / K + 4.0 * m[c] * m[d] * exy -
                          3.0 * m[c] * m[c] * m[d] * m[d];
      const double vc = s.s2[c][c] / K - m[c] * m[c], vd = s.s2[d][d] / K - m[d] * m[d];
      k22[c][d] = mu22 - vc * vd - 2.0 * m2 * m2;  // joint fourth cumulant k(c,c,d,d)
    }
}

double PassMoments::third_moment(size_t i, int c) const {
  const Sums& s = sums_[i];
  const double K = k_, m = s.s1[c] / K;
  return s.s3[c][c] / K - 3.0 * m * s.s2[c][c] / K + 2.0 * m * m * m;
}

Image PassMoments::sample_sd() const {
  Image img(w_, h_);
  double cov[3][3], k22[3][3];
  for (size_t i = 0; i < sums_.size(); ++i) {
    pixel_cumulants(i, cov, k22);
    for (int c = 0; c < 3; ++c) img.pixels[i][c] = std::sqrt(std::max(0.0, n0_ * cov[c][c]));
  }
  return img;
}

RelMSEModel PassMoments::model(const Image& reference) const {
  if (reference.width != w_ || reference.height != h_) throw std::invalid_argument("PassMoments::model: size differs");
  if (k_ < 2) throw std::logic_error("PassMoments::model: needs two passes at least");
  RelMSEModel m;
  m.reference_samples = k_ * n0_;
  const double n0 = n0_;
  double cov[3][3], k22[3][3];
  for (size_t i = 0; i < sums_.size(); ++i) {
    pixel_cumulants(i, cov, k22);
    double w[3];
    for (int c = 0; c < 3; ++c) w[c] = 1.0 / (reference.pixels[i][c] * reference.pixels[i][c] + kRelMSEEpsilon);
    for (int c = 0; c < 3; ++c) {
      // The weight w(R) and the variance estimate come from the same passes:
      // a pixel whose passes drew more bright rare samples has a larger R
      // (smaller w) and a larger variance, so sum w s is biased low by
      // w'(R) Cov(R, s) = w'(R) n0 m3 / K to first order (m3 the passes'
      // third central moment). Added back here; measured, it is 0.5-2% of a
      // for heavy-tailed pixels, as large as sd[S] at 16 spp.
      const double r = reference.pixels[i][c], dw = -2.0 * r * w[c] * w[c];
      m.a += w[c] * n0 * cov[c][c] - dw * n0 * third_moment(i, c) / k_;
      for (int d = 0; d < 3; ++d) {
        const double s = n0 * cov[c][d];                // per-sample covariance
        m.c2 += 2.0 * w[c] * w[d] * s * s;
        m.c3 += w[c] * w[d] * n0 * n0 * n0 * k22[c][d];  // per-sample cumulant
      }
    }
  }
  const double terms = 3.0 * double(sums_.size());
  m.a /= terms;
  m.c2 /= terms * terms;
  m.c3 /= terms * terms;
  return m;
}

}  // namespace pt::error_model
