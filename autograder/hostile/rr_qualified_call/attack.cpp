// Hostile: Part 4's tests count the BSDF samples of each path in a path guard,
// which stops a path longer than roulette lets one be (tests/support/
// part4_scenes.h). The tests' counting BSDF was a subclass of DiffuseBSDF
// that counted in its override of sample_f; a qualified call,
// `DiffuseBSDF::sample_f`, is not virtual and skips the override, in one
// process and in the worker alike. This path samples that way wherever the
// BSDF is a DiffuseBSDF, and has no roulette at depths 6 to 1000 with
// p <= 0.5 (elsewhere it keeps it, so that only what roulette's tests see is
// at stake, not the time limits of the Cornell box, depth 5, of
// Furnace.FullEstimate, p >= 0.7, or of the high-albedo test, depth
// 10,000): its paths end after 40 bounces, past the guard's limit for
// p = 0.3 (37). The tests' BSDF now holds the diffuse BSDF instead of being
// one: the cast finds none, every sample counts, and the guard stops those
// paths of RussianRoulette.KeepsTheMean, which also sees from the estimates
// themselves that no path ends early; the hidden RaisesTheVariance sees no
// variance rise.
#include "core/frame.h"
#include "render/pathtracer.h"

namespace {
pt::Spectrum sample_unseen(const pt::BSDF& bsdf, const pt::Vec3& wo, pt::Vec3* wi, double* pdf, pt::Rng& rng) {
  if (const auto* d = dynamic_cast<const pt::DiffuseBSDF*>(&bsdf)) return d->pt::DiffuseBSDF::sample_f(wo, wi, pdf, rng);
  return bsdf.sample_f(wo, wi, pdf, rng);
}
}  // namespace
