// P3T2: zero_bounce_radiance, the light emitted towards the camera. Exact.
#include "common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part3;

GRADED_TEST(ZeroBounce, FrontOfAnEmitterGivesItsRadianceTheBackNothing, "P3T2", 1, Visible) {
  // An area light facing down (-z) at z = 1, a glowing diffuse wall facing +x
  // at x = -2, and an emitting sphere. Emitters are one-sided: the radiance
  // leaves the front only.
  Scene s;
  const Spectrum Le(3.0, 2.0, 1.0), Lw(0.5, 0.25, 4.0), Ls(7.0, 7.0, 0.5);
  s.add_area_light(Le, {0, 0, 1}, {1, 0, 0}, {0, -1, 0});
  s.add_area_light(Lw, {-2, 0, 0}, {0, 1, 0}, {0, 0, 1}, Spectrum(0.5));  // reflects too
  s.add_sphere({3, 3, 3}, 0.5, s.add_bsdf<EmissionBSDF>(Ls));
  s.build();
  for (Vec3 from : {Vec3(0, 0, 0), Vec3(0.3, -0.2, -2), Vec3(-3, 1, 0.9)}) {
    EXPECT_EQ(seen(s, from, {0.1, 0.2, 1}), Le) << "front of the area light, seen from " << from;
  }
  for (Vec3 from : {Vec3(0, 0, 2), Vec3(0.4, 0.3, 1.01), Vec3(2, -1, 3)})
    EXPECT_EQ(seen(s, from, {0.1, -0.2, 1}), Spectrum(0.0)) << "back of the area light, seen from " << from;
  EXPECT_EQ(seen(s, {0, 0.1, 0.05}, {-2, 0.2, 0.1}), Lw) << "front of the glowing wall";
  EXPECT_EQ(seen(s, {-3, 0.1, 0.05}, {-2, 0.2, 0.1}), Spectrum(0.0)) << "back of the glowing wall";
  EXPECT_EQ(seen(s, {3, 3, 0}, {3, 3, 3}), Ls) << "emitting sphere from outside";
  EXPECT_EQ(seen(s, {3, 3, 3}, {3, 3, 4}), Spectrum(0.0)) << "emitting sphere from inside (its back)";
}

}  // namespace
}  // namespace pt
