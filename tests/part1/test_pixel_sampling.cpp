// P1T2 PathTracer::raytrace_pixel (fixed sample count). The radiance estimate
// is replaced by a scripted one that records every camera ray it is given, so
// that the test knows each sample's value and can map each ray back to the
// image point it went through. That mapping inverts the camera under test
// (numerically, through Camera::generate_ray itself), not the closed form of
// P1T1: a mistake in generate_ray does not cost P1T2 points, as long as
// generate_ray runs and gives different directions for different points.
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "render/pathtracer.h"
#include "support/graded.h"
#include "support/part1_builders.h"
#include "support/scripted_tracer.h"
#include "support/seed.h"
#include "support/statistics.h"

namespace pt::test::part1 {
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
  // The same, starting from where a pinhole camera as P1T1 describes it
  // would have sent the ray (one or two Gauss-Newton steps instead of ten,
  // for tests that map thousands of rays); from the pixel centre when that
  // point is nowhere near the pixel.
  Vec2 pixel_point_near_pinhole(const Ray& r, int x, int y) const {
    const Camera& cam = scene.camera;
    const Vec3 c = glm::transpose(cam.c2w) * r.d;
    Vec2 guess(x + 0.5, y + 0.5);
    if (c.z < 0.0) {
      const Vec2 sensor(-c.x / c.z / std::tan(glm::radians(cam.hfov) / 2.0),
                        -c.y / c.z / std::tan(glm::radians(cam.vfov) / 2.0));
      const Vec2 g((sensor.x + 1.0) / 2.0 * settings.width, (sensor.y + 1.0) / 2.0 * settings.height);
      if (g.x > x - 1.0 && g.x < x + 2.0 && g.y > y - 1.0 && g.y < y + 2.0) guess = g;
    }
    return pixel_point(r, guess);
  }

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

// Every one of the N samples of a pixel is uniform in it, the first as much
// as the others (a loop that sends one sample through the centre and jitters
// the rest weighs the centre 1/N extra: a biased pixel). Pearson's chi-square
// over 17 cells of the pixel: a 4 x 4 grid, minus a centre square of side 0.1,
// which is the 17th cell (expected counts: samples x area; the centre cell
// expects 5 or 5.1, the grid's cells 30 to 32), once with N = 2 (250
// pixels) and once with N = 16 (32 pixels), each at alpha = 5e-6 (critical
// value 54.1 at 16 degrees of freedom): a correct loop fails the test with
// probability 1e-5 (Sidak). Measured over seed offsets 0 to 19: the
// reference 10.7-29.6 (N = 2) and 10.5-23.5 (N = 16); the first sample
// through the centre 12,231 and 189 (251 and 35 samples in the centre cell).
// Positions are where the rays went, whatever the numbers drawn to put them.
GRADED_TEST_F(PixelSampling, EverySampleIsUniformInThePixel, "P1T2", 0.5, Visible) {
  const int x = 6, y = 1;
  const double side = 0.1;  // the centre cell
  const struct {
    int ns, pixels;
  } runs[] = {{2, 250}, {16, 32}};
  Rng rng(seed(8));
  for (const auto& run : runs) {
    std::vector<double> observed(17, 0.0), expected(17, 0.0);
    const double n = double(run.ns) * run.pixels;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const bool touches_centre = (i == 1 || i == 2) && (j == 1 || j == 2);  // loses a quarter of the centre cell
        expected[j * 4 + i] = n / 16.0 - (touches_centre ? n * side * side / 4.0 : 0.0);
      }
    expected[16] = n * side * side;
    for (int k = 0; k < run.pixels; ++k) {
      ScriptedTracer t = tracer(run.ns);
      t.raytrace_pixel(x, y, rng);
      ASSERT_EQ(t.rays.size(), size_t(run.ns)) << where(x, y, run.ns);
      for (const Ray& r : t.rays) {
        const Vec2 p = pixel_point_near_pinhole(r, x, y) - Vec2(x, y);
        if (inversion_failed_) return;
        if (std::abs(p.x - 0.5) < side / 2 && std::abs(p.y - 0.5) < side / 2) {
          observed[16] += 1;
        } else {
          const int i = std::clamp(int(p.x * 4.0), 0, 3), j = std::clamp(int(p.y * 4.0), 0, 3);
          observed[j * 4 + i] += 1;
        }
      }
    }
    stats::ChiSquareResult chi = stats::chi_square_test(observed, expected, 5e-6);
    testing::Test::RecordProperty("chi_square_ns" + std::to_string(run.ns), std::to_string(chi.statistic));
    EXPECT_TRUE(chi.passed()) << "The samples of a pixel are not uniform in it: " << observed[16] << " of " << n
                              << " landed in the square of side " << side << " around the centre (expected "
                              << expected[16]
                              << "). Every sample, the first one too, goes through (x + u, y + v) with (u, v) = "
                                 "rng.uniform2(); only ns_aa == 1 uses the centre.\n"
                              << chi.describe() << "\n" << where(x, y, run.ns) << " (" << run.pixels << " calls)";
  }
}

// Section 2 of the handout: the radiance estimates draw from the generator
// passed in too, after the jitter, as one stream. The scripted estimate
// returns the number it draws. Generators seeded alike give the same pixel,
// others another; and no number an estimate drew is one the jitter drew (a
// copy of the generator would hand the estimate the numbers the next
// sample's jitter then draws again). A correct loop fails only if one of 8
// estimates' numbers falls within 1e-9 of one of 16 jitter offsets: < 3e-7.
GRADED_TEST_F(PixelSampling, EstimatesDrawFromTheRngPassedIn, "P1T2", 0.5, Visible) {
  const int ns = 8, x = 3, y = 2;
  struct Drawing : ScriptedTracer {
    using ScriptedTracer::ScriptedTracer;
    Spectrum est_radiance_global_illumination(const Ray& r, Rng& rng) const override {
      ScriptedTracer::est_radiance_global_illumination(r, rng);
      drawn.push_back(rng.uniform());
      return Spectrum(drawn.back());
    }
    mutable std::vector<double> drawn;
  };
  settings.ns_aa = ns;
  Drawing first(scene, settings, constant(Spectrum(0.0))), second(first), third(first);
  auto pixel = [&](const Drawing& t, uint64_t s) {
    Rng rng(s);
    return t.raytrace_pixel(x, y, rng).radiance;
  };
  const Spectrum a = pixel(first, seed(9)), again = pixel(second, seed(9)), other = pixel(third, seed(9) + 1);
  ASSERT_EQ(first.drawn.size(), size_t(ns)) << where(x, y, ns);
  EXPECT_EQ(a, again) << "Two calls with generators seeded alike gave different pixels (" << a << " and " << again
                      << ") from a radiance estimate that returns the number it draws from the rng it is given: pass "
                         "the rng you were given on to est_radiance_global_illumination.\n"
                      << where(x, y, ns);
  EXPECT_NE(a, other) << "Generators seeded differently gave the same pixel " << a
                      << ": the radiance estimates do not draw from the rng passed in.\n"
                      << where(x, y, ns);
  for (size_t k = 0; k < first.rays.size(); ++k) {
    const Vec2 p = pixel_point(first.rays[k], x, y) - Vec2(x, y);
    for (size_t e = 0; e < first.drawn.size(); ++e)
      for (double u : {p.x, p.y})
        ASSERT_GT(std::abs(first.drawn[e] - u), 1e-9)
            << "Radiance estimate " << e << " drew " << first.drawn[e] << ", the jitter offset of sample " << k
            << " (" << p << "): the estimates were given a copy of the generator, which repeats the numbers the "
               "jitter draws. Pass the rng itself (by reference) to est_radiance_global_illumination.\n"
            << where(x, y, ns);
  }
}

}  // namespace
}  // namespace pt::test::part1
