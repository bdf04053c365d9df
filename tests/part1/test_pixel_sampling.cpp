// P1T2 PathTracer::raytrace_pixel (fixed sample count). The radiance estimate
// is replaced by a scripted one that records every camera ray it is given, so
// that the test knows each sample's value and can map each ray back to the
// image point it went through. That mapping inverts the camera under test
// (numerically, through Camera::generate_ray itself), not the closed form of
// P1T1: a mistake in generate_ray does not cost P1T2 points, as long as
// generate_ray runs and gives different directions for different points.
#include <algorithm>
#include <functional>
#include <sstream>

#include "render/pathtracer.h"
#include "support/graded.h"
#include "support/part1_builders.h"
#include "support/scripted_tracer.h"
#include "support/seed.h"

namespace pt::test::p1 {
namespace {

// An 8 x 6 image (not square, so that width and height cannot be mixed up)
// seen by a camera that is not at the origin.
class PixelSampling : public ::testing::Test {
 protected:
  PixelSampling() {
    pose = {Vec3(1.0, 2.0, 3.0), Vec3(-1.0, 1.5, -2.0), Vec3(0.0, 1.0, 0.0), 64.0, 50.0};
    scene.camera = make_camera(pose);
    settings.width = 8;
    settings.height = 6;
  }
  ScriptedTracer tracer(int ns_aa) {
    settings.ns_aa = ns_aa;
    return ScriptedTracer(scene, settings, constant(Spectrum(1.0)));
  }
  std::string where(int x, int y, int ns_aa) const {
    std::ostringstream os;
    os << "pixel (" << x << ", " << y << ") of a " << settings.width << " x " << settings.height
       << " image, ns_aa = " << ns_aa << ", " << scene.camera;
    return os.str();
  }
  // The point of the image, in pixel units, that a camera ray went through:
  // the (u, v) at which the camera's own generate_ray gives the ray's
  // direction, found by Gauss-Newton from `guess` (pixel units). Fails the
  // test if there is no such point.
  Vec2 pixel_point(const Ray& r, Vec2 guess) const {
    const Camera& cam = scene.camera;
    const Vec2 size(settings.width, settings.height);
    auto dir = [&](Vec2 q) { return glm::normalize(cam.generate_ray(q.x / size.x, q.y / size.y).d); };
    const Vec3 target = glm::normalize(r.d);
    Vec2 p = guess;
    for (int it = 0; it < 30 && glm::length(dir(p) - target) > 1e-14; ++it) {
      const double h = 1e-6;
      Vec3 res = dir(p) - target;
      Vec3 ju = (dir(p + Vec2(h, 0)) - dir(p - Vec2(h, 0))) / (2 * h);
      Vec3 jv = (dir(p + Vec2(0, h)) - dir(p - Vec2(0, h))) / (2 * h);
      double a = glm::dot(ju, ju), b = glm::dot(ju, jv), c = glm::dot(jv, jv);
      double g1 = glm::dot(ju, res), g2 = glm::dot(jv, res), det = a * c - b * b;
      if (!(std::abs(det) > 0)) break;
      p -= Vec2(c * g1 - b * g2, a * g2 - b * g1) / det;
    }
    if (!(glm::length(dir(p) - target) < 1e-10) && !inversion_failed_) {
      inversion_failed_ = true;  // report once, not for every sample
      ADD_FAILURE() << "No image point of this camera's generate_ray gives the direction of the camera ray " << r
                    << " that raytrace_pixel traced; build camera rays with camera->generate_ray.";
    }
    return p;
  }
  Vec2 pixel_point(const Ray& r, int x, int y) const { return pixel_point(r, Vec2(x + 0.5, y + 0.5)); }

  LookAt pose;
  Scene scene;
  mutable bool inversion_failed_ = false;
  RenderSettings settings;
};

GRADED_TEST_F(PixelSampling, TakesExactlyNsAaSamples, "P1T2", 0.5, Visible) {
  for (int ns : {1, 2, 4, 7, 16}) {
    ScriptedTracer t = tracer(ns);
    Rng rng(seed(1));
    t.raytrace_pixel(3, 2, rng);
    ASSERT_EQ(t.rays.size(), size_t(ns)) << "radiance estimates for " << where(3, 2, ns)
                                         << "\nTake exactly settings.ns_aa samples.";
  }
}

GRADED_TEST_F(PixelSampling, RecordsSampleCount, "P1T2", 0.5, Visible) {
  for (int ns : {1, 3, 16}) {
    ScriptedTracer t = tracer(ns);
    Rng rng(seed(2));
    PixelEstimate e = t.raytrace_pixel(1, 4, rng);
    ASSERT_EQ(e.num_samples, ns) << "PixelEstimate::num_samples for " << where(1, 4, ns)
                                 << "\nReturn the number of samples taken.";
  }
}

GRADED_TEST_F(PixelSampling, AveragesTheSamples, "P1T2", 0.5, Visible) {
  for (int ns : {1, 2, 5, 16}) {
    // Sample k has radiance (k+1, 2(k+1), 0.5): the mean is ((n+1)/2, n+1, 0.5).
    ScriptedTracer t = tracer(ns);
    t.script = {"sample k (from 0) = (k+1, 2(k+1), 0.5)", [](int k) { return Spectrum(k + 1.0, 2.0 * (k + 1.0), 0.5); }};
    Rng rng(seed(3));
    PixelEstimate e = t.raytrace_pixel(5, 0, rng);
    Vec3 expected((ns + 1) / 2.0, ns + 1.0, 0.5);
    ASSERT_TRUE(VecNear("the pixel radiance", e.radiance, expected, 1e-12))
        << "\nThe pixel's radiance is the mean of its samples; here sample k (from 0) returned (k+1, 2(k+1), 0.5).\n"
        << where(5, 0, ns);
  }
}

GRADED_TEST_F(PixelSampling, SingleSampleGoesThroughPixelCentre, "P1T2", 0.5, Visible) {
  const int pixels[][2] = {{0, 0}, {7, 5}, {3, 2}, {6, 1}};
  for (auto [x, y] : pixels) {
    ScriptedTracer t = tracer(1);
    Rng rng(seed(4));
    t.raytrace_pixel(x, y, rng);
    ASSERT_EQ(t.rays.size(), 1u) << where(x, y, 1);
    Vec2 centre((x + 0.5) / settings.width, (y + 0.5) / settings.height);
    ASSERT_TRUE(VecNear("the ray direction", t.rays[0].d, scene.camera.generate_ray(centre.x, centre.y).d, 1e-12))
        << "\nWith ns_aa = 1 the ray goes through the pixel centre, image point " << centre << " (pixel coordinates "
        << Vec2(x + 0.5, y + 0.5) << "); it went through pixel coordinates " << pixel_point(t.rays[0], x, y) << ".\n"
        << where(x, y, 1) << "\nray " << t.rays[0];
  }
}

GRADED_TEST_F(PixelSampling, SamplesStayInsideTheirPixel, "P1T2", 1, Visible) {
  // Pixel (x, y) covers [x, x+1] x [y, y+1] in pixel coordinates, that is
  // [x/w, (x+1)/w] x [y/h, (y+1)/h] of the image; 1e-9 absorbs rounding.
  const int pixels[][2] = {{0, 0}, {7, 5}, {3, 2}, {0, 5}, {7, 0}, {2, 4}};
  const int ns = 64;
  for (auto [x, y] : pixels) {
    ScriptedTracer t = tracer(ns);
    Rng rng(seed(5));
    t.raytrace_pixel(x, y, rng);
    ASSERT_EQ(t.rays.size(), size_t(ns)) << where(x, y, ns);
    for (size_t k = 0; k < t.rays.size(); ++k) {
      Vec2 p = pixel_point(t.rays[k], x, y);
      bool inside = p.x >= x - 1e-9 && p.x <= x + 1 + 1e-9 && p.y >= y - 1e-9 && p.y <= y + 1 + 1e-9;
      ASSERT_TRUE(inside) << "Sample " << k << " went through pixel coordinates " << p << ", outside its pixel ["
                          << x << ", " << x + 1 << "] x [" << y << ", " << y + 1
                          << "]. Jitter by rng.uniform2() in [0,1)^2 from the pixel's corner, then divide by the "
                             "image width (x) and height (y).\n"
                          << where(x, y, ns) << "\nray " << t.rays[k];
    }
  }
}

GRADED_TEST_F(PixelSampling, SamplesAreJitteredAcrossThePixel, "P1T2", 1, Visible) {
  // With n = 256 uniform samples (u, v) in the pixel:
  //  - some u < 1/4 and some u > 3/4 (same for v): a correct sampler misses
  //    one of these with probability 4 * 0.75^256 < 1e-31;
  //  - the mean of u (and of v) is within 0.1 of 1/2: 5.5 standard errors
  //    (sd 1/sqrt(12 * 256) = 0.018), p < 1e-7;
  //  - u and v are uncorrelated: |corr| < 0.4 is 6.4 standard errors
  //    (sd 1/16), p < 1e-9.
  // Power (99%): a mean offset of 0.14 or more from 1/2, a correlation of
  // 0.55 or more.
  const int ns = 256, x = 2, y = 3;
  ScriptedTracer t = tracer(ns);
  Rng rng(seed(6));
  t.raytrace_pixel(x, y, rng);
  ASSERT_EQ(t.rays.size(), size_t(ns)) << where(x, y, ns);
  std::vector<double> u, v;
  for (const Ray& r : t.rays) {
    Vec2 p = pixel_point(r, x, y);
    u.push_back(p.x - x);
    v.push_back(p.y - y);
  }
  auto mean = [](const std::vector<double>& a) {
    double s = 0;
    for (double q : a) s += q;
    return s / a.size();
  };
  double mu = mean(u), mv = mean(v);
  double suv = 0, suu = 0, svv = 0;
  for (int k = 0; k < ns; ++k) {
    suv += (u[k] - mu) * (v[k] - mv);
    suu += (u[k] - mu) * (u[k] - mu);
    svv += (v[k] - mv) * (v[k] - mv);
  }
  double corr = suu > 0 && svv > 0 ? suv / std::sqrt(suu * svv) : 1.0;
  auto [umin, umax] = std::minmax_element(u.begin(), u.end());
  auto [vmin, vmax] = std::minmax_element(v.begin(), v.end());
  std::ostringstream got;
  got << "offsets inside the pixel: u in [" << *umin << ", " << *umax << "] mean " << mu << ", v in [" << *vmin
      << ", " << *vmax << "] mean " << mv << ", corr(u, v) = " << corr << "\n"
      << where(x, y, ns);
  EXPECT_TRUE(*umin < 0.25 && *umax > 0.75 && *vmin < 0.25 && *vmax > 0.75)
      << "Samples must spread over the whole pixel (jitter each with rng.uniform2()).\n"
      << got.str();
  EXPECT_TRUE(std::abs(mu - 0.5) < 0.1 && std::abs(mv - 0.5) < 0.1)
      << "Sample offsets must be uniform in the pixel, with mean 1/2.\n"
      << got.str();
  EXPECT_LT(std::abs(corr), 0.4) << "The x and y offsets must be independent random numbers.\n" << got.str();
}

GRADED_TEST_F(PixelSampling, JitterComesFromTheRngPassedIn, "P1T2", 0.5, Visible) {
  // Section 2 of the handout: use the rng you are given. 16 samples of pixel
  // (3, 2); exact comparisons of the rays (support/scripted_tracer.h).
  const int ns = 16;
  EXPECT_TRUE(test::jitter_comes_from(
      [&](Rng& rng) {
        ScriptedTracer t = tracer(ns);
        t.raytrace_pixel(3, 2, rng);
        return t.rays;
      },
      seed(7)))
      << where(3, 2, ns);
}

}  // namespace
}  // namespace pt::test::p1
