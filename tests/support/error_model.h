#pragma once
// The error model's estimator (render/relmse_model.h has the model itself and
// its derivation).
//
// The constants come from the passes of the reference render (PassMoments):
// K independent renders of n0 spp each give, per pixel, the covariance and
// joint fourth cumulants of an n0-spp estimate; per-sample values are n0
// times the covariance and n0^3 times the cumulants.
#include <vector>

#include "render/image.h"
#include "render/relmse_model.h"

namespace pt::error_model {

// Per-pixel moments of K independent renders ("passes") of n0 spp each, the
// same scene and settings with different seeds. Accumulates in doubles,
// shifted by the first pass (so that a bright, nearly constant pixel keeps
// its precision in the fourth moments).
class PassMoments {
 public:
  PassMoments(int width, int height, int pass_samples);
  void add(const Image& pass);
  int passes() const { return k_; }
  int width() const { return w_; }
  int height() const { return h_; }

  Image mean() const;  // the average of the passes: the reference image
  // Per-sample standard deviation of each pixel and channel: sqrt(n0 * the
  // unbiased variance of the passes).
  Image sample_sd() const;
  // a, c2 and c3 with the weights of `reference` (the image as stored, so
  // that the model describes exactly what a comparison computes).
  RelMSEModel model(const Image& reference) const;

 private:
  struct Sums {
    double s1[3], s2[3][3], s3[3][3], s4[3][3];  // sums of x_c, x_c x_d, x_c^2 x_d, x_c^2 x_d^2
  };
  // Pass-level covariance and joint fourth cumulants k(c,c,d,d) of pixel i.
  void pixel_cumulants(size_t i, double cov[3][3], double k22[3][3]) const;
  double third_moment(size_t i, int c) const;  // of the passes, central
  int w_, h_, n0_, k_ = 0;
  std::vector<Spectrum> shift_;
  std::vector<Sums> sums_;
};

}  // namespace pt::error_model
