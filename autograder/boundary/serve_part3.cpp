// The worker's Part 3: the verifier's calls (proxies_part3.cpp) answered by
// the student's task functions, on the scene the verifier sent last.
#include "render/pathtracer.h"
#include "repeated_call.h"
#include "scene/bsdf.h"
#include "worker_scenes.h"

namespace pt::boundary {
namespace {

DiffuseBSDF diffuse_from(Reader& in) {
  const auto reflectance = in.get<Spectrum>();
  return DiffuseBSDF(reflectance, in.get<Spectrum>());
}

// An estimator's call: the tracer over the scene named, the ray and the hit.
template <Spectrum (PathTracer::*estimator)(const Ray&, const Intersection&, Rng&) const>
void serve_estimate(Reader& in, Writer& out) {
  const Scene& scene = scene_named(in);
  const PathTracer tracer(scene, in.get<RenderSettings>());
  const auto ray = in.get<Ray>();
  Intersection hit;
  get_scene_hit(in, hit, scene);
  answer_run<Spectrum>(in, out, [&](Rng& rng) { return (tracer.*estimator)(ray, hit, rng); });
}

}  // namespace

void serve_task_calls(Link& link) {
  serve_scene_definitions(link);
  link.on(Call::DiffuseF, [](Reader& in, Writer& out) {
    const DiffuseBSDF bsdf = diffuse_from(in);
    const auto wo = in.get<Vec3>(), wi = in.get<Vec3>();
    out.put(bsdf.f(wo, wi));
  });
  link.on(Call::DiffuseSampleF, [](Reader& in, Writer& out) {
    const DiffuseBSDF bsdf = diffuse_from(in);
    const auto wo = in.get<Vec3>();
    answer_run<BsdfSample>(in, out, [&](Rng& rng) {
      BsdfSample s{Spectrum(0.0), Vec3(0.0), 0.0};
      s.f = bsdf.sample_f(wo, &s.wi, &s.pdf, rng);
      return s;
    });
  });
  link.on(Call::ZeroBounce, [](Reader& in, Writer& out) {
    const Scene& scene = scene_named(in);
    const PathTracer tracer(scene, in.get<RenderSettings>());
    const auto ray = in.get<Ray>();
    Intersection hit;
    get_scene_hit(in, hit, scene);
    out.put(tracer.zero_bounce_radiance(ray, hit));
  });
  link.on(Call::DirectHemisphere, serve_estimate<&PathTracer::estimate_direct_lighting_hemisphere>);
  link.on(Call::DirectImportance, serve_estimate<&PathTracer::estimate_direct_lighting_importance>);
  link.on(Call::OneBounce, serve_estimate<&PathTracer::one_bounce_radiance>);
}

}  // namespace pt::boundary
