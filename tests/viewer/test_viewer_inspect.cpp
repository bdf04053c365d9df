// The viewer's BVH walk and pixel inspector against the scene they show.
#include <cmath>

#include "geometry/sphere.h"
#include "viewer_fixture.h"

namespace pt::test {
namespace {

json box(const BBox& b) {
  return {{"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}};
}

// Walks two levels down and back up, comparing each answer with the tree.
TEST(ViewerInspect, BvhWalkAnswersFromTheTree) {
  ServedViewer v("cornell_bunny.json");
  const BVHNode* root = v.scene().bvh->root();
  ASSERT_TRUE(root && root->l && root->r);
  struct Step {
    std::string path;
    const BVHNode* node;
  };
  const BVHNode* lr = root->l->r.get();
  ASSERT_NE(lr, nullptr);
  for (const Step& s : {Step{"", root}, Step{"l", root->l.get()}, Step{"lr", lr}, Step{"r", root->r.get()}}) {
    SCOPED_TRACE("path '" + s.path + "'");
    const json n = v.get("/api/bvh?path=" + s.path);
    EXPECT_EQ(n["depth"], s.path.size());
    EXPECT_EQ(n["count"], s.node->size());
    EXPECT_EQ(n["start"], s.node->start);
    EXPECT_EQ(n["bbox"], box(s.node->bb));
    EXPECT_EQ(n["leaf"], s.node->is_leaf());
    EXPECT_EQ(n["sah"]["leaf_cost"], double(s.node->size()));
    if (!s.node->is_leaf()) {
      const double split = (s.node->l->bb.surface_area() * s.node->l->size() + s.node->r->bb.surface_area() * s.node->r->size()) /
                           s.node->bb.surface_area();
      EXPECT_DOUBLE_EQ(n["sah"]["split_cost"].get<double>(), split);
      // A split worth making costs less than testing every primitive.
      EXPECT_LT(n["sah"]["subtree_cost"].get<double>(), n["sah"]["leaf_cost"].get<double>());
    }
    // The box is drawn (12 edges, all in front of this camera) and so are
    // the primitives: three edges per triangle, up to the drawing cap.
    EXPECT_EQ(n["box_segments"].size(), 12u);
    EXPECT_EQ(n["primitive_segments"].size(), 3 * n["primitives_drawn"].get<size_t>());
    EXPECT_EQ(n["primitives_drawn"], std::min<size_t>(s.node->size(), 4000));
  }
  // The root's children partition its primitives.
  EXPECT_EQ(root->l->size() + root->r->size(), root->size());
  EXPECT_EQ(v.get("/api/bvh")["count"], v.scene().primitives.size());
}

TEST(ViewerInspect, BvhWalkRefusesAPathOutOfTheTree) {
  ServedViewer v("tests/one_sphere.json");  // three primitives: the root is a leaf
  ASSERT_TRUE(v.scene().bvh->root()->is_leaf());
  const json e = v.get("/api/bvh?path=l", 400);
  EXPECT_NE(e["error"].get<std::string>().find("leaves the tree"), std::string::npos) << e.dump();
  const json bad = v.get("/api/bvh?path=x", 400);
  EXPECT_NE(bad["error"].get<std::string>().find("expected l or r"), std::string::npos) << bad.dump();
}

// The centre pixel of an odd-sized image looks straight at the unit sphere
// from (0, 0, 3): its first vertex is the sphere at (0, 0, 1), normal +z.
TEST(ViewerInspect, PixelPathFirstVertexIsTheKnownHit) {
  RenderSettings s = ServedViewer::small_settings();
  s.width = s.height = 33;
  s.max_ray_depth = 4;
  ServedViewer v("tests/one_sphere.json", {}, s);
  v.wait_until_finished();
  long sphere = -1;
  for (size_t i = 0; i < v.scene().primitives.size(); ++i)
    if (dynamic_cast<const Sphere*>(v.scene().primitives[i].get())) sphere = long(i);
  ASSERT_GE(sphere, 0);
  const json p = v.get("/api/pixel?x=16&y=16");
  ASSERT_FALSE(p.contains("error")) << p.dump();
  EXPECT_EQ(p["samples"], 4);
  EXPECT_GT(p["value"][0].get<double>(), 0.0);
  ASSERT_GE(p["vertices"].size(), 1u);
  const json& first = p["vertices"][0];
  EXPECT_EQ(first["primitive"], sphere);
  EXPECT_EQ(first["primitive_kind"], "sphere");
  EXPECT_NEAR(first["t"].get<double>(), 2.0, 1e-9);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(first["point"][i].get<double>(), i == 2 ? 1.0 : 0.0, 1e-9);
    EXPECT_NEAR(first["normal"][i].get<double>(), i == 2 ? 1.0 : 0.0, 1e-9);
  }
  // Projected back onto the pixel it came from.
  EXPECT_NEAR(first["pixel"][0].get<double>(), 16.5, 1e-6);
  EXPECT_NEAR(first["pixel"][1].get<double>(), 16.5, 1e-6);
  // A diffuse vertex: a BSDF sample with a positive pdf, one light sample,
  // and the first bounce never roulettes.
  EXPECT_GT(first["bsdf_sample"]["pdf"].get<double>(), 0.0);
  EXPECT_EQ(first["light_samples"].size(), 1u);
  EXPECT_EQ(first["russian_roulette"]["p"], 1.0);
  EXPECT_EQ(first["russian_roulette"]["survives"], true);
  EXPECT_EQ(p["warnings"], json::array());
  // Every later vertex that roulettes uses --rr.
  for (size_t k = 1; k < p["vertices"].size(); ++k) {
    if (p["vertices"][k].contains("russian_roulette")) {
      EXPECT_EQ(p["vertices"][k]["russian_roulette"]["p"], 0.7);
    }
  }
  // A pixel in a corner misses the sphere: the path escapes at once.
  const json miss = v.get("/api/pixel?x=0&y=0");
  ASSERT_EQ(miss["vertices"].size(), 1u);
  EXPECT_EQ(miss["vertices"][0]["escaped"], true);
}

// A BSDF that reflects a negative amount and samples NaN: what a sign or a
// 0/0 slip in a student's BSDF looks like. The inspector marks both.
struct BrokenBSDF : BSDF {
  Spectrum f(const Vec3&, const Vec3&) const override { return Spectrum(-0.2); }
  Spectrum sample_f(const Vec3&, Vec3* wi, double* pdf, Rng&) const override {
    *wi = Vec3(0.0, 0.0, 1.0);
    *pdf = std::nan("");
    return Spectrum(std::nan(""));
  }
};

TEST(ViewerInspect, PixelPathMarksNegativeAndNaNValues) {
  const json p = centre_path_on_sphere_of<BrokenBSDF>();
  ASSERT_FALSE(p.contains("error")) << p.dump();
  const std::string warnings = p["warnings"].dump();
  EXPECT_NE(warnings.find("vertex 0 direct light is negative"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("vertex 0 BSDF value is NaN"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("vertex 0 BSDF pdf is NaN"), std::string::npos) << warnings;
  // The path stops where the pdf is unusable.
  EXPECT_EQ(p["vertices"].size(), 1u);
}

}  // namespace
}  // namespace pt::test
