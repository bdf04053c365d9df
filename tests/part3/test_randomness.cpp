// Part 3's drawing tasks take their random numbers from the Rng passed in,
// and only from it (skeleton/render/pathtracer.h, handouts/part3.md section
// 0): two generators in the same state give the same answer, and the one
// passed in moves (support/draws_from.h). Every set-up below draws on every
// call: a cosine-weighted direction, hemisphere directions, points on an area
// light. Exact comparisons; a correct solution fails with probability 2^-32
// per call. Boundary: the generator's state crosses with each call and comes
// back with its answer.
#include <tuple>

#include "common.h"
#include "support/draws_from.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

constexpr int kCalls = 4;  // continuous answers: one call would do

GRADED_TEST(DirectRandomness, SampleFDrawsOnlyFromItsRng, "P3T1", 0.5, Visible) {
  const DiffuseBSDF bsdf(Spectrum(0.3, 0.5, 0.7));
  const Vec3 wo = glm::normalize(Vec3(0.2, -0.4, 1.0));
  EXPECT_TRUE(test::draws_only_from(
      [&](Rng& rng) {
        Vec3 wi(0.0);
        double pdf = -1.0;
        const Spectrum f = bsdf.sample_f(wo, &wi, &pdf, rng);
        return std::make_tuple(f, wi, pdf);
      },
      test::seed(3620), kCalls, "DiffuseBSDF::sample_f"));
}

// The 0.8 x 0.6 area light above a receiver: every estimator draws.
void check_estimator(Method m, const RenderSettings& s, uint64_t seed) {
  const Lit lit = moderate_light();
  const PathTracer tracer(lit.scene, s);
  EXPECT_TRUE(test::draws_only_from([&](Rng& rng) { return estimate(tracer, lit.aim, m, rng); }, test::seed(seed),
                                    kCalls, name(m)));
}

GRADED_TEST(DirectRandomness, HemisphereDrawsOnlyFromItsRng, "P3T3", 0.5, Visible) {
  check_estimator(Method::Hemisphere, settings_with(4, true), 3621);
}

GRADED_TEST(DirectRandomness, LightSamplingDrawsOnlyFromItsRng, "P3T4", 0.5, Visible) {
  check_estimator(Method::Importance, settings_with(4), 3622);
}

GRADED_TEST(DirectRandomness, OneBounceDrawsOnlyFromItsRng, "P3T5", 0.5, Visible) {
  check_estimator(Method::OneBounce, settings_with(4), 3623);
  check_estimator(Method::OneBounce, settings_with(4, true), 3624);
}

GRADED_EXTENSION_TEST(DirectRandomness, MisDrawsOnlyFromItsRng, "P3T6", 0.5, Visible) {
  check_estimator(Method::Mis, settings_with(4), 3625);
}

}  // namespace
}  // namespace pt
