// The verifier's Part 3: each task function asks the worker (README.md beside
// this file). The tracer's scene crosses once (refer_to), the hit as indices
// into it; the estimators and the sampler, which the tests call in loops,
// answer in runs (repeated_call.h).
#include "render/pathtracer.h"
#include "repeated_call.h"
#include "scene/bsdf.h"
#include "verifier_link.h"

namespace pt {
namespace {

using boundary::BsdfSample;
using boundary::Call;
using boundary::call_worker;
using boundary::Reader;
using boundary::Writer;

Spectrum spectrum_from(const std::string& answer) {
  return boundary::read_answer([&] {
    Reader out(answer);
    const auto value = out.get<Spectrum>();
    out.finish();
    return value;
  });
}

// One of the estimators, on the tracer's scene and settings.
template <Call call>
Spectrum estimate(const PathTracer& tracer, const Ray& r, const Intersection& isect, Rng& rng) {
  thread_local boundary::RepeatedCall<Spectrum> runs(call, call == Call::DirectHemisphere ? "estimate_direct_lighting_hemisphere"
                                                           : call == Call::DirectImportance ? "estimate_direct_lighting_importance"
                                                                                            : "one_bounce_radiance");
  const auto link = boundary::hold_link();
  const boundary::SceneRef scene = boundary::refer_to(*tracer.scene);
  Writer args(256);
  args.put(scene.id).put(tracer.settings).put(r);
  boundary::put_scene_hit(args, isect, scene.index);
  return boundary::read_answer([&] { return runs.next(args, rng, call_worker); });
}

}  // namespace

Spectrum DiffuseBSDF::f(const Vec3& wo, const Vec3& wi) const {
  Writer in;
  in.put(reflectance).put(emission).put(wo).put(wi);
  return spectrum_from(call_worker(Call::DiffuseF, in));
}

Spectrum DiffuseBSDF::sample_f(const Vec3& wo, Vec3* wi, double* pdf, Rng& rng) const {
  thread_local boundary::RepeatedCall<BsdfSample> runs(Call::DiffuseSampleF, "DiffuseBSDF::sample_f");
  Writer args;
  args.put(reflectance).put(emission).put(wo);
  const BsdfSample s = boundary::read_answer([&] { return runs.next(args, rng, call_worker); });
  *wi = s.wi;
  *pdf = s.pdf;
  return s.f;
}

Spectrum PathTracer::zero_bounce_radiance(const Ray& r, const Intersection& isect) const {
  const auto link = boundary::hold_link();
  const boundary::SceneRef ref = boundary::refer_to(*scene);
  Writer in;
  in.put(ref.id).put(settings).put(r);
  boundary::put_scene_hit(in, isect, ref.index);
  return spectrum_from(call_worker(Call::ZeroBounce, in));
}

Spectrum PathTracer::estimate_direct_lighting_hemisphere(const Ray& r, const Intersection& isect, Rng& rng) const {
  return estimate<Call::DirectHemisphere>(*this, r, isect, rng);
}

Spectrum PathTracer::estimate_direct_lighting_importance(const Ray& r, const Intersection& isect, Rng& rng) const {
  return estimate<Call::DirectImportance>(*this, r, isect, rng);
}

Spectrum PathTracer::one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const {
  return estimate<Call::OneBounce>(*this, r, isect, rng);
}

}  // namespace pt
