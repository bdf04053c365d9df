// Part 5 graded tests: PathTracer::raytrace_pixel_adaptive (P5T1).
//
// The radiance estimate is replaced by a script (ScriptedTracer overrides the
// virtual est_radiance_global_illumination), so each test knows exactly what
// every camera sample returns, counts the samples and records the rays. The
// camera is the reference Camera::generate_ray (in the part5 binary only part 5
// is the student's). Stopping counts use the closed form of
// test_sample_adaptively.cpp: for a repeating pattern, stop at the first batch
// multiple n with n - 1 >= T = (1.96 sp / (tol mu))^2, or at ns_aa.
#include <cmath>
#include <sstream>

#include "scripted.h"
#include "support/graded.h"
#include "support/seed.h"

namespace pt {
namespace {

using test::part5::adaptive_settings;
using test::part5::alternating;
using test::part5::constant;
using test::part5::describe;
using test::part5::scene_with_camera;
using test::part5::ScriptedTracer;
using test::part5::spectrum_near;

// Where a camera ray crosses the image, in pixel units: the inverse of
// Camera::generate_ray((px / width), (py / height)), (0, 0) at the bottom-left.
Vec2 pixel_position(const Camera& cam, const RenderSettings& s, const Ray& r) {
  Vec3 d = glm::transpose(cam.c2w) * r.d;  // camera space; c2w is a rotation
  double sx = d.x / -d.z, sy = d.y / -d.z;  // on the sensor plane z = -1
  double u = (sx / std::tan(glm::radians(cam.hfov) / 2.0) + 1.0) / 2.0;
  double v = (sy / std::tan(glm::radians(cam.vfov) / 2.0) + 1.0) / 2.0;
  return {u * s.width, v * s.height};
}

GRADED_TEST(PixelAdaptive, ConstantPixelStopsAfterOneBatch, "P5T1", 0.5, Visible) {
  Scene scene = scene_with_camera();
  RenderSettings s = adaptive_settings(8, 6, 512, 16, 0.05);
  const Spectrum c(0.25, 0.5, 0.75);
  ScriptedTracer tracer(scene, s, constant(c));
  Rng rng(test::seed(5100));
  PixelEstimate p = tracer.raytrace_pixel_adaptive(3, 2, rng);
  std::string in = describe(tracer, 3, 2);
  EXPECT_EQ(tracer.calls, 16) << in << "\na constant pixel stops after one batch of settings.samples_per_batch = 16";
  EXPECT_EQ(p.num_samples, tracer.calls)
      << in << "\nnum_samples must record how many radiance samples the pixel took (" << tracer.calls << ")";
  EXPECT_TRUE(spectrum_near(p.radiance, c)) << in << "\nreturned " << p.radiance << ", expected " << c;
}

GRADED_TEST(PixelAdaptive, UsesTheSettingsAndNeverExceedsNsAa, "P5T1", 0.5, Visible) {
  Scene scene = scene_with_camera();
  const struct {
    int ns_aa, batch;
    double tol;
    Spectrum a, b;
    int expected;
    const char* why;
  } cases[] = {
      // Alternating 3, 1: mu = 2, sp = 1, tol 0.16: T = 37.52 -> batch 8 stops at 40.
      {1000, 8, 0.16, Spectrum(3), Spectrum(1), 40, "T = 37.52: first multiple of 8 with n - 1 >= T is 40"},
      // Same pixel, batch 12: checks at 36 (35 < 37.52) and 48.
      {1000, 12, 0.16, Spectrum(3), Spectrum(1), 48, "T = 37.52: first multiple of 12 with n - 1 >= T is 48"},
      // Alternating 1, 0 with tol 0.05: T = 1536.6, never met: ns_aa is the cap.
      {20, 8, 0.05, Spectrum(1), Spectrum(0), 20, "T = 1536.6 is never met: stop at ns_aa = 20"},
      {5, 8, 0.05, Spectrum(1), Spectrum(0), 5, "T = 1536.6 is never met: stop at ns_aa = 5 (less than a batch)"},
  };
  for (const auto& k : cases) {
    RenderSettings s = adaptive_settings(8, 6, k.ns_aa, k.batch, k.tol);
    ScriptedTracer tracer(scene, s, alternating(k.a, k.b));
    Rng rng(test::seed(5101));
    PixelEstimate p = tracer.raytrace_pixel_adaptive(5, 1, rng);
    std::string in = describe(tracer, 5, 1);
    EXPECT_EQ(tracer.calls, k.expected) << in << "\n" << k.why;
    EXPECT_LE(tracer.calls, s.ns_aa) << in << "\nnever more than settings.ns_aa samples";
    EXPECT_EQ(p.num_samples, tracer.calls) << in << "\nnum_samples must record the samples taken";
    Spectrum want = (double((tracer.calls + 1) / 2) * k.a + double(tracer.calls / 2) * k.b) / double(tracer.calls);
    EXPECT_TRUE(spectrum_near(p.radiance, want))
        << in << "\nreturned " << p.radiance << ", the mean of the " << tracer.calls << " samples taken is " << want;
  }
}

GRADED_TEST(PixelAdaptive, RaysPassThroughThePixel, "P5T1", 1, Visible) {
  // Every camera ray of pixel (x, y) crosses the image inside
  // [x, x+1] x [y, y+1] (pixel units, (0, 0) bottom-left of a width x height
  // image), i.e. generate_ray((x + u) / width, (y + v) / height) with u, v in [0, 1).
  // Samples are jittered: among 64 uniform samples, each half of the pixel (left
  // and right, bottom and top) gets at least one. A correct jitter misses a
  // given half with probability 2^-64, so this fails with probability < 4 * 2^-64 per pixel.
  Scene scene = scene_with_camera();
  const double eps = 1e-6;  // pixel units; the inversion is exact to ~1e-12
  const int pixels[][2] = {{5, 1}, {0, 0}, {7, 5}, {2, 4}};
  for (const auto& px : pixels) {
    const int x = px[0], y = px[1];
    RenderSettings s = adaptive_settings(8, 6, 64, 8, 0.05);
    // Alternating 1, 0 never meets the rule (T = 1536.6), so all 64 samples are taken.
    ScriptedTracer tracer(scene, s, alternating(Spectrum(1), Spectrum(0)));
    Rng rng = Rng::for_pixel(test::seed(5102), x, y);
    tracer.raytrace_pixel_adaptive(x, y, rng);
    std::string in = describe(tracer, x, y);
    ASSERT_EQ(int(tracer.rays.size()), 64) << in << "\nexpected all 64 samples (the rule is never met)";
    bool left = false, right = false, bottom = false, top = false;
    int outside = 0, off_camera = 0;
    std::ostringstream first_outside, first_off_camera;
    for (size_t i = 0; i < tracer.rays.size(); ++i) {
      const Ray& r = tracer.rays[i];
      Vec2 q = pixel_position(scene.camera, s, r);
      if (!(q.x >= x - eps && q.x <= x + 1 + eps && q.y >= y - eps && q.y <= y + 1 + eps) && outside++ == 0)
        first_outside << "sample " << i << ": ray " << r << " crosses the image at pixel coordinates " << q;
      if (!(glm::length(r.o - scene.camera.pos) < 1e-9) && off_camera++ == 0)
        first_off_camera << "sample " << i << ": ray " << r;
      left |= q.x < x + 0.5, right |= q.x > x + 0.5, bottom |= q.y < y + 0.5, top |= q.y > y + 0.5;
    }
    EXPECT_EQ(outside, 0) << in << "\n" << outside << " of 64 rays miss pixel [" << x << ", " << x + 1 << "] x [" << y
                          << ", " << y + 1 << "] (pixel units, (0, 0) bottom-left); the first: "
                          << first_outside.str();
    EXPECT_EQ(off_camera, 0) << in << "\n" << off_camera << " of 64 rays do not start at the camera "
                             << scene.camera.pos << "; the first: " << first_off_camera.str();
    EXPECT_TRUE(left && right && bottom && top)
        << in << "\n64 samples should be jittered over the whole pixel; seen in the left half: " << left
        << ", right: " << right << ", bottom: " << bottom << ", top: " << top;
  }
  // ns_aa = 1: the one sample goes through the pixel centre (as raytrace_pixel does).
  RenderSettings s = adaptive_settings(8, 6, 1, 8, 0.05);
  ScriptedTracer tracer(scene, s, constant(Spectrum(0.5)));
  Rng rng = Rng::for_pixel(test::seed(5103), 5, 1);
  PixelEstimate p = tracer.raytrace_pixel_adaptive(5, 1, rng);
  std::string in = describe(tracer, 5, 1);
  ASSERT_EQ(int(tracer.rays.size()), 1) << in << "\nns_aa = 1 allows one sample";
  EXPECT_EQ(p.num_samples, 1) << in;
  Vec2 q = pixel_position(scene.camera, s, tracer.rays[0]);
  EXPECT_TRUE(std::abs(q.x - 5.5) < eps && std::abs(q.y - 1.5) < eps)
      << in << "\nwith ns_aa = 1 the ray goes through the pixel centre (5.5, 1.5); it crosses at " << q;
}

GRADED_TEST(PixelAdaptive, UsesOnlyTheRngItIsGiven, "P5T1", 0.5, Visible) {
  // 16 samples of pixel (5, 1) (alternating 1, 0 never meets the rule);
  // exact comparisons of the rays. Boundary: exact, fails only if the jitter
  // ignores the rng passed in (or one number in 2^32 repeats).
  const Scene scene = scene_with_camera();
  const RenderSettings s = adaptive_settings(8, 6, 16, 4, 0.05);
  EXPECT_TRUE(test::jitter_comes_from(
      [&](Rng& rng) {
        ScriptedTracer tracer(scene, s, alternating(Spectrum(1), Spectrum(0)));
        tracer.raytrace_pixel_adaptive(5, 1, rng);
        return tracer.rays;
      },
      test::seed(5104)))
      << describe(ScriptedTracer(scene, s, alternating(Spectrum(1), Spectrum(0))), 5, 1);
}

}  // namespace
}  // namespace pt
