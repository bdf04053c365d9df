// Hidden P3T2 test: surfaces that do not emit give nothing.
#include "../common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

GRADED_TEST(ZeroBounce, NonEmittersGiveNothing, "P3T2", 1, Hidden) {
  Scene s;
  s.add_quad({0, 0, 0}, {2, 0, 0}, {0, 2, 0}, s.add_bsdf<DiffuseBSDF>(Spectrum(0.9)));
  s.add_sphere({0, 0, 2}, 0.5, s.add_bsdf<DiffuseBSDF>(Spectrum(0.3)));
  s.add_light<PointLight>(Spectrum(10.0), Vec3(0, 0, 1));
  s.add_light<DirectionalLight>(Spectrum(10.0), Vec3(0, 0, -1));
  s.build();
  EXPECT_EQ(seen(s, {0.2, 0.1, 1}, {0.1, 0.3, 0}), Spectrum(0.0)) << "lit diffuse floor, front";
  EXPECT_EQ(seen(s, {0.2, 0.1, -1}, {0.1, 0.3, 0}), Spectrum(0.0)) << "diffuse floor, back";
  EXPECT_EQ(seen(s, {0, 0, 4}, {0, 0, 2}), Spectrum(0.0)) << "diffuse sphere";
}

}  // namespace
}  // namespace pt
