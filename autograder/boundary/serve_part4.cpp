// The worker's Part 4: the verifier's calls (proxies_part4.cpp) answered by
// the student's task functions, on the scene the verifier sent last, with the
// path guard's state the verifier sent.
#include "path_guard_copy.h"
#include "render/pathtracer.h"
#include "repeated_call.h"
#include "worker_scenes.h"

namespace pt::boundary {
namespace {

// One estimate under the guard: it starts where the verifier's was, and a
// path it stops is an answer that says so (the run goes on).
template <class Estimate>
auto guarded(int64_t samples, int64_t limit, Estimate estimate) {
  return [=](Rng& rng) {
    PathGuardCopy& guard = path_guard_copy();
    guard.samples = samples;
    guard.limit = limit;
    GuardedEstimate e{Spectrum(0.0), 0, 0};
    try {
      e.radiance = estimate(rng);
    } catch (const PathGuardCopy::Tripped&) {
      e.tripped = 1;
    }
    e.samples = guard.samples;
    return e;
  };
}

}  // namespace

void serve_task_calls(Link& link) {
  serve_scene_definitions(link);
  link.on(Call::AtLeastOneBounce, [](Reader& in, Writer& out) {
    const Scene& scene = scene_named(in);
    const PathTracer tracer(scene, in.get<RenderSettings>());
    const auto ray = in.get<Ray>();
    const auto samples = in.get<int64_t>(), limit = in.get<int64_t>();
    Intersection hit;
    get_scene_hit(in, hit, scene);
    answer_run<GuardedEstimate>(in, out, guarded(samples, limit, [&](Rng& rng) {
      return tracer.at_least_one_bounce_radiance(ray, hit, rng);
    }));
  });
  link.on(Call::GlobalIllumination, [](Reader& in, Writer& out) {
    const Scene& scene = scene_named(in);
    const PathTracer tracer(scene, in.get<RenderSettings>());
    const auto ray = in.get<Ray>();
    const auto samples = in.get<int64_t>(), limit = in.get<int64_t>();
    answer_run<GuardedEstimate>(in, out, guarded(samples, limit, [&](Rng& rng) {
      return tracer.est_radiance_global_illumination(ray, rng);
    }));
  });
}

}  // namespace pt::boundary
