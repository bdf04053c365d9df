// Hidden P3T1 test: the pdf sample_f writes, per sample.
#include "../bsdf_cases.h"
#include "../common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

// Exact per sample (1e-9): no statistics.
GRADED_TEST(DiffuseBSDF, SampleFReturnsThePdfOfItsDirection, "P3T1", 1, Hidden) {
  // Exact, per sample: wi is a unit vector in the upper hemisphere, the pdf
  // written is cos(theta)/pi of that wi (the density the chi-square test
  // checks), positive wherever f is, and the value returned is f(wo, wi).
  DiffuseBSDF bsdf(kColour);
  Rng rng(test::seed(302));
  for (const Vec3& wo : some_directions())
    for (int i = 0; i < 20000; ++i) {
      const auto [f, wi, pdf] = sample_f(bsdf, wo, rng, -1.0);
      ASSERT_NEAR(glm::length(wi), 1.0, 1e-9) << "wi " << wi;
      ASSERT_GE(wi.z, 0.0) << "wi " << wi << " is below the surface";
      ASSERT_NEAR(pdf, wi.z / kPi, 1e-9) << "wi " << wi;
      if (wi.z > 1e-9) {
        ASSERT_GT(pdf, 0.0) << "pdf 0 where f > 0, wi " << wi;
      }
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(f[c], kColour[c] / kPi, 1e-12) << "sample_f must return f(wo, wi)";
    }
}

}  // namespace
}  // namespace pt
