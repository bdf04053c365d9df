// The tiled renderer: determinism across threads, NaN accounting, failures.
#include <gtest/gtest.h>

#include <cmath>
#include <mutex>
#include <set>

#include <pthread.h>

#include "core/not_implemented.h"
#include "render/limits.h"
#include "render/renderer.h"
#include "support/scene_builders.h"

namespace pt {
namespace {

RenderSettings small_settings() {
  RenderSettings s;
  s.width = 24;
  s.height = 20;  // not a multiple of the tile size: partial tiles are exercised
  s.ns_aa = 4;
  s.ns_area_light = 2;
  s.max_ray_depth = 3;
  s.seed = 7;
  return s;
}

TEST(Renderer, SameImageWithOneAndTwoThreads) {
  Scene scene = test::make_cornell_box();
  PathTracer tracer(scene, small_settings());
  RenderResult one = render(tracer, 1), two = render(tracer, 2);
  ASSERT_TRUE(one.ok()) << one.error;
  ASSERT_TRUE(two.ok()) << two.error;
  for (size_t i = 0; i < one.image.pixels.size(); ++i)
    ASSERT_EQ(one.image.pixels[i], two.image.pixels[i]) << "pixel " << i % 24 << "," << i / 24;
  EXPECT_EQ(one.work.rays, two.work.rays);
  EXPECT_EQ(one.nonfinite_pixels, 0u);
}

TEST(Renderer, SeedChangesTheNoise) {
  Scene scene = test::make_cornell_box();
  RenderSettings a = small_settings(), b = small_settings();
  b.seed = a.seed + 1;
  RenderResult ra = render(PathTracer(scene, a), 1), rb = render(PathTracer(scene, b), 1);
  int differ = 0;
  for (size_t i = 0; i < ra.image.pixels.size(); ++i) differ += ra.image.pixels[i] != rb.image.pixels[i];
  EXPECT_GT(differ, int(ra.image.pixels.size()) / 2);
}

TEST(Renderer, RecordsSampleCountsAndWork) {
  Scene scene = test::make_cornell_box();
  RenderSettings s = small_settings();
  RenderResult r = render(PathTracer(scene, s), 2);
  for (int c : r.sample_counts) ASSERT_EQ(c, s.ns_aa);
  // Every camera sample traces at least its camera ray.
  EXPECT_GE(r.work.rays, uint64_t(s.width) * s.height * s.ns_aa);
  EXPECT_GT(r.work.primitive_tests, 0u);
}

// Every box test through node->bb and every call into a scene primitive must
// reach the counters, whoever makes them: a student's traversal bumps no
// counter itself, and `pathtracer` must still report its work per ray. The
// calls are made here the way any traversal makes them, over every node.
struct CountedCalls {
  uint64_t boxes = 0, primitive_calls = 0;
  void visit_all(const BVHNode* node, const std::vector<Primitive*>& prims, const Ray& r) {
    std::vector<const BVHNode*> todo{node};
    while (!todo.empty()) {
      const BVHNode* n = todo.back();
      todo.pop_back();
      double t0 = r.min_t, t1 = r.max_t;
      n->bb.intersect(r, t0, t1);
      ++boxes;
      Intersection isect;
      for (size_t i = n->start; i < n->end && !n->l; ++i, ++primitive_calls) prims[i]->intersect(r, &isect);
      if (n->l) todo.push_back(n->l.get());
      if (n->r) todo.push_back(n->r.get());
    }
  }
};

TEST(WorkCounters, FrameworkCountsEveryBoxAndPrimitiveTest) {
  Scene scene = test::make_cornell_box();
  CountedCalls calls;
  take_work_counters();
  Rng rng(3);
  for (int i = 0; i < 20; ++i)
    calls.visit_all(scene.bvh->root(), scene.bvh->primitives(), scene.camera.generate_ray(rng.uniform(), rng.uniform()));
  WorkCounters w = take_work_counters();
  EXPECT_EQ(w.node_visits, calls.boxes) << "each node->bb.intersect call is one node visit";
  EXPECT_EQ(w.primitive_tests, calls.primitive_calls) << "each call into a scene primitive is one test";
  EXPECT_GT(calls.primitive_calls, 100u);
}

// Radiance that is NaN in one column and infinite in another.
class PoisonedTracer : public PathTracer {
 public:
  using PathTracer::PathTracer;
  Spectrum est_radiance_global_illumination(const Ray& r, Rng&) const override {
    if (r.d.x < -0.2) return Spectrum(std::nan(""));
    if (r.d.x > 0.2) return Spectrum(INFINITY, 0, 0);
    return Spectrum(1.0);
  }
};

TEST(Renderer, CountsNonFinitePixelsAndWritesThemBlack) {
  Scene scene = test::make_cornell_box();
  RenderSettings s = small_settings();
  s.ns_aa = 1;
  PoisonedTracer tracer(scene, s);
  RenderResult r = render(tracer, 2);
  ASSERT_TRUE(r.ok()) << r.error;
  uint64_t black = 0, finite = 0;
  for (const Spectrum& p : r.image.pixels) {
    finite += is_finite(p);
    black += p == Spectrum(0.0);
  }
  EXPECT_EQ(finite, r.image.pixels.size());
  EXPECT_GT(r.nonfinite_pixels, 0u);
  EXPECT_EQ(r.nonfinite_pixels, black);
}

class ThrowingTracer : public PathTracer {
 public:
  using PathTracer::PathTracer;
  Spectrum est_radiance_global_illumination(const Ray&, Rng&) const override {
    throw NotImplemented("P4T3 PathTracer::est_radiance_global_illumination");
  }
};

TEST(Renderer, ATaskExceptionStopsTheRenderWithItsMessage) {
  Scene scene = test::make_cornell_box();
  ThrowingTracer tracer(scene, small_settings());
  RenderResult r = render(tracer, 2);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("not implemented: P4T3"), std::string::npos) << r.error;
}

// Settings beyond render/limits.h end in an error naming the bound, before
// anything is allocated or rendered (the command line checks them first; this
// is for every other caller).
TEST(Renderer, RefusesSettingsBeyondTheLimits) {
  Scene scene = test::make_cornell_box();
  struct Case {
    const char* what;
    void (*edit)(RenderSettings&);
    int threads;
    const char* message;
  };
  const Case cases[] = {
      {"width past INT_MAX - 15", [](RenderSettings& s) { s.width = 2147483640; }, 1, "image width 2147483640 is not in [1, 16384]"},
      {"too many pixels", [](RenderSettings& s) { s.width = s.height = 16384; }, 1, "at most 33554432"},
      {"depth", [](RenderSettings& s) { s.max_ray_depth = kMaxRayDepth + 1; }, 1, "maximum ray depth 10001 is not in [0, 10000]"},
      {"threads", [](RenderSettings&) {}, kMaxThreads + 1, "threads 1025 is not in [1, 1024]"},
      {"no threads", [](RenderSettings&) {}, 0, "threads 0 is not in [1, 1024]"},
      {"rr NaN", [](RenderSettings& s) { s.rr_continue_prob = std::nan(""); }, 1, "Russian roulette"},
  };
  for (const Case& c : cases) {
    RenderSettings s = small_settings();
    c.edit(s);
    RenderResult r = render(PathTracer(scene, s), c.threads);
    EXPECT_FALSE(r.ok()) << c.what;
    EXPECT_NE(r.error.find(c.message), std::string::npos) << c.what << ": " << r.error;
    EXPECT_TRUE(r.image.pixels.empty()) << c.what;
  }
}

// Records the stack size of every thread that estimates a pixel.
class StackSizeRecorder : public PathTracer {
 public:
  using PathTracer::PathTracer;
  Spectrum est_radiance_global_illumination(const Ray&, Rng&) const override {
    pthread_attr_t attr;
    size_t size = 0;
    if (pthread_getattr_np(pthread_self(), &attr) == 0) {
      pthread_attr_getstacksize(&attr, &size);
      pthread_attr_destroy(&attr);
    }
    std::lock_guard<std::mutex> lock(mutex);
    stack_sizes.insert(size);
    return Spectrum(1.0);
  }
  mutable std::mutex mutex;
  mutable std::set<size_t> stack_sizes;
};

// The depth bound is measured against kRenderThreadStackBytes: every pixel,
// with one thread too, must be estimated on a thread that has it (not on the
// caller's thread, whose stack `ulimit -s` decides).
TEST(Renderer, EstimatesOnThreadsWithTheStackTheDepthBoundAssumes) {
  Scene scene = test::make_cornell_box();
  for (int threads : {1, 3}) {
    StackSizeRecorder tracer(scene, small_settings());
    RenderResult r = render(tracer, threads);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.threads, threads);
    ASSERT_FALSE(tracer.stack_sizes.empty());
    for (size_t size : tracer.stack_sizes)
      EXPECT_GE(size, kRenderThreadStackBytes) << threads << " threads: a pixel was estimated on a " << size
                                               << "-byte stack";
  }
}

}  // namespace
}  // namespace pt
