// The verifier's Part 4: each task function asks the worker (README.md beside
// this file). The scene crosses as Part 3's does, the estimates in runs; the
// tests' instrumented BSDFs cross as the worker's copies of them, and their
// path guard as its state (path_guard_copy.h): a path the worker's guard
// stopped is stopped here by the test's own guard, with its own message.
#include <algorithm>
#include <typeinfo>

#include "path_guard_copy.h"
#include "render/pathtracer.h"
#include "repeated_call.h"
#include "support/part4_scenes.h"
#include "verifier_link.h"

namespace pt {
namespace {

using boundary::BsdfKind;
using boundary::Call;
using boundary::GuardedEstimate;
using boundary::Writer;

bool encode_test_bsdf(Writer& w, const BSDF& b) {
  if (typeid(b) == typeid(test::part4::GuardedDiffuse)) {
    const auto& d = static_cast<const test::part4::GuardedDiffuse&>(b);
    w.put(BsdfKind::GuardedDiffuse).put(d.albedo()).put(d.emission());
    return true;
  }
  if (typeid(b) == typeid(test::part4::NormalMirror)) {
    w.put(BsdfKind::NormalMirror);
    return true;
  }
  return false;
}

const bool kEncoderSet = (boundary::set_bsdf_encoder(encode_test_bsdf), true);

}  // namespace

namespace boundary {
// Field by field: the struct's padding is whatever the worker left there.
bool same_answer(const GuardedEstimate& a, const GuardedEstimate& b) {
  return test::same_bits(a.radiance, b.radiance) && a.samples == b.samples && a.tripped == b.tripped;
}
}  // namespace boundary

namespace {

// An estimate from the worker, with the path guard's state going and coming back.
template <Call call>
Spectrum estimate(const PathTracer& tracer, const Ray& r, const Intersection* isect, Rng& rng) {
  thread_local boundary::RepeatedCall<GuardedEstimate> runs(
      call, call == Call::AtLeastOneBounce ? "at_least_one_bounce_radiance" : "est_radiance_global_illumination");
  test::part4::PathGuard& guard = test::part4::path_guard();
  GuardedEstimate e;
  {
    const auto link = boundary::hold_link();
    const boundary::SceneRef scene = boundary::refer_to(*tracer.scene);
    Writer args(256);
    args.put(scene.id).put(tracer.settings).put(r).put(guard.samples).put(guard.limit);
    if (isect) boundary::put_scene_hit(args, *isect, scene.index);
    e = boundary::read_answer([&] { return runs.next(args, rng, boundary::call_worker); });
  }
  guard.samples = e.samples;
  if (e.tripped) {
    guard.samples = std::max(guard.samples, guard.limit);
    guard.count();  // throws, saying what it says in one process
  }
  return e.radiance;
}

}  // namespace

Spectrum PathTracer::at_least_one_bounce_radiance(const Ray& r, const Intersection& isect, Rng& rng) const {
  return estimate<Call::AtLeastOneBounce>(*this, r, &isect, rng);
}

Spectrum PathTracer::est_radiance_global_illumination(const Ray& r, Rng& rng) const {
  return estimate<Call::GlobalIllumination>(*this, r, nullptr, rng);
}

}  // namespace pt
