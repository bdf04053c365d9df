// A scene across the process boundary (boundary/scene_codec.h): rebuilt in the
// worker from its bytes, it holds the same BSDFs and lights, field for field,
// and answers every ray as the original does, its hits naming the objects
// that correspond; what cannot cross is refused by name.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "core/rng.h"
#include "geometry/sphere.h"
#include "scene_codec.h"

namespace pt::boundary {
namespace {

Scene every_kind() {
  Scene s;
  const BSDF* wall = s.add_bsdf<DiffuseBSDF>(Spectrum(0.2, 0.5, 0.9), Spectrum(0.1, 0.0, 0.3));
  const BSDF* lamp = s.add_bsdf<EmissionBSDF>(Spectrum(4.0, 3.0, 2.0));
  s.add_quad({0, 0, -1}, {4, 0, 0}, {0, 4, 0}, wall);
  Mesh m;
  m.positions = {{-1, -1, 0.5}, {1, -1, 0.3}, {0, 1, 0.7}, {0.5, 0.5, -0.2}};
  m.faces = {{0, 1, 2}, {1, 3, 2}};
  m.bsdf = wall;
  s.add_mesh(m);  // normals computed: not unit-axis values
  s.add_sphere({0.3, -0.2, 0.1}, 0.35, lamp);
  s.add_sphere({-0.8, 0.6, 0.0}, 0.2, nullptr);
  s.add_light<PointLight>(Spectrum(10.0), Vec3(0.2, 0.1, 1.0));
  s.add_light<DirectionalLight>(Spectrum(3.0), Vec3(0.1, 0.3, -1.0));  // normalised by its constructor
  s.add_area_light(Spectrum(5.0), {0, 0, 2}, {0.8, 0, 0}, {0, -0.6, 0});
  s.add_light<SkyLight>(Spectrum(0.25, 0.5, 0.75));
  s.camera = Camera({0.1, -0.2, 3.0}, {0, 0, 0}, {0, 1, 0}, 50.0, 40.0);
  s.build();
  return s;
}

std::unique_ptr<Scene> round_trip(const Scene& s, SceneIndex& index) {
  Writer w;
  put_scene(w, s, index);
  Reader r(w.bytes());
  auto copy = get_scene(r);
  r.finish();
  return copy;
}

template <class T>
bool same_bytes(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

TEST(SceneCodec, BsdfsAndLightsCrossFieldForField) {
  const Scene s = every_kind();
  SceneIndex index;
  const auto copy = round_trip(s, index);
  ASSERT_EQ(copy->bsdfs.size(), s.bsdfs.size());
  const auto& d0 = dynamic_cast<const DiffuseBSDF&>(*s.bsdfs[0]);
  const auto& d1 = dynamic_cast<const DiffuseBSDF&>(*copy->bsdfs[0]);
  EXPECT_TRUE(same_bytes(d0.reflectance, d1.reflectance) && same_bytes(d0.emission, d1.emission));
  EXPECT_TRUE(same_bytes(dynamic_cast<const EmissionBSDF&>(*s.bsdfs[1]).radiance,
                         dynamic_cast<const EmissionBSDF&>(*copy->bsdfs[1]).radiance));
  ASSERT_EQ(copy->lights.size(), s.lights.size());
  const auto& dir0 = dynamic_cast<const DirectionalLight&>(*s.lights[1]);
  const auto& dir1 = dynamic_cast<const DirectionalLight&>(*copy->lights[1]);
  EXPECT_TRUE(same_bytes(dir0.direction, dir1.direction)) << "the direction is sent, not normalised again";
  const auto& a0 = dynamic_cast<const AreaLight&>(*s.lights[2]);
  const auto& a1 = dynamic_cast<const AreaLight&>(*copy->lights[2]);
  EXPECT_TRUE(same_bytes(a0.direction, a1.direction) && same_bytes(a0.position, a1.position) &&
              same_bytes(a0.dim_x, a1.dim_x) && same_bytes(a0.dim_y, a1.dim_y) && a0.area() == a1.area());
  EXPECT_TRUE(same_bytes(s.background(Vec3(0, 0, 1)), copy->background(Vec3(0, 0, 1)))) << "the sky's radiance";
  EXPECT_TRUE(same_bytes(s.camera, copy->camera));
}

TEST(SceneCodec, TheCopyAnswersEveryRayAsTheOriginalDoes) {
  const Scene s = every_kind();
  SceneIndex index;
  const auto copy = round_trip(s, index);
  ASSERT_EQ(copy->primitives.size(), s.primitives.size());
  Rng rng(11);
  int hits = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 o(4 * rng.uniform() - 2, 4 * rng.uniform() - 2, 3.0 * rng.uniform() - 1.5);
    const Vec2 u = rng.uniform2();
    const double z = 2 * u.x - 1, phi = 2 * kPi * u.y, rxy = std::sqrt(std::max(0.0, 1 - z * z));
    const Ray r(o, Vec3(rxy * std::cos(phi), rxy * std::sin(phi), z));
    const Ray r0 = r, r1 = r;  // a query shrinks its ray's max_t
    Intersection h0, h1;
    const bool hit0 = s.intersect(r0, &h0), hit1 = copy->intersect(r1, &h1);
    ASSERT_EQ(hit0, hit1) << "ray " << i;
    ASSERT_EQ(s.has_intersection(r), copy->has_intersection(r)) << "ray " << i;
    if (!hit0) continue;
    ++hits;
    ASSERT_EQ(h0.t, h1.t) << "ray " << i;
    ASSERT_TRUE(same_bytes(h0.n, h1.n)) << "ray " << i;
    // The hit record crossing the other way names the copy's own objects.
    Writer w;
    put_scene_hit(w, h0, index);
    Reader rd(w.bytes());
    Intersection crossed;
    get_scene_hit(rd, crossed, *copy);
    rd.finish();
    EXPECT_EQ(crossed.primitive, copy->primitives[index.primitives.at(h0.primitive)].get()) << "ray " << i;
    EXPECT_EQ(crossed.bsdf, h1.bsdf) << "ray " << i;
    EXPECT_EQ(crossed.t, h0.t);
  }
  EXPECT_GT(hits, 1000) << "the rays must hit something for this test to say anything";
}

TEST(SceneCodec, AHitOnNothingOrSomethingElseCrossesAsSuch) {
  const Scene s = every_kind();
  SceneIndex index;
  const auto copy = round_trip(s, index);
  const Sphere stranger(Vec3(0.0), 1.0, nullptr);
  const DiffuseBSDF stranger_bsdf(Spectrum(0.5));
  for (const auto& [primitive, bsdf] : {std::pair<const Primitive*, const BSDF*>{nullptr, nullptr},
                                        {&stranger, &stranger_bsdf}}) {
    Intersection h;
    h.t = 1.5;
    h.primitive = primitive;
    h.bsdf = bsdf;
    Writer w;
    put_scene_hit(w, h, index);
    Reader rd(w.bytes());
    Intersection crossed;
    get_scene_hit(rd, crossed, *copy);
    if (!primitive) {
      EXPECT_EQ(crossed.primitive, nullptr);
      EXPECT_EQ(crossed.bsdf, nullptr);
      continue;
    }
    ASSERT_NE(crossed.primitive, nullptr);
    ASSERT_NE(crossed.bsdf, nullptr);
    for (const auto& p : copy->primitives) EXPECT_NE(crossed.primitive, p.get()) << "not one of the scene's";
    for (const auto& b : copy->bsdfs) EXPECT_NE(crossed.bsdf, b.get()) << "not one of the scene's";
  }
}

// A subclass that adds to the framework's type (as the tests' instrumented
// BSDFs do) would lose what it adds in a copy: refused, by name.
class CountingDiffuse : public DiffuseBSDF {
 public:
  using DiffuseBSDF::DiffuseBSDF;
};

TEST(SceneCodec, ASubclassOfAFrameworkTypeIsRefusedByName) {
  Scene s;
  s.add_quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, s.add_bsdf<CountingDiffuse>(Spectrum(0.5)));
  s.build();
  SceneIndex index;
  Writer w;
  try {
    put_scene(w, s, index);
    FAIL() << "a scene with a test's own BSDF crossed";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("CountingDiffuse"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pt::boundary
