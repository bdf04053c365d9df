// Scene loading: the shipped scenes load as described, meshes are placed by
// their transforms, and every kind of bad input is refused with a message
// that names the file and the place (line:column for syntax, a JSON pointer
// for content).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <unistd.h>

#include "geometry/sphere.h"
#include "io/scene_loader.h"
#include "pt_source_dir.h"
#include "support/assertions.h"

namespace fs = std::filesystem;

namespace pt {
namespace {

const fs::path kScenes = fs::path(PT_SOURCE_DIR) / "scenes";

// A scene file that is valid as it stands; tests splice errors into copies.
const char* kMinimal = R"({"shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";

template <class L>
int count_lights(const Scene& s) {
  int n = 0;
  for (const auto& l : s.lights) n += dynamic_cast<const L*>(l.get()) != nullptr;
  return n;
}

using test::contains;

// Each test writes its files into a directory of its own.
class SceneFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("pt_scene_loader_" + std::to_string(getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }

  // The message load_scene throws for `text`; fails the test if it loads.
  std::string error_of(const std::string& text, const std::string& name = "scene.json") {
    std::string path = write(name, text);
    try {
      load_scene(path);
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << "the message should start with the file: " << e.what();
      return e.what();
    }
    ADD_FAILURE() << "loaded without an error:\n" << text;
    return "";
  }

  // Expects `text` to be refused with "<file>: <pointer>: ...<fragment>...".
  void expect_content_error(const std::string& text, const std::string& pointer, const std::string& fragment) {
    std::string path = (dir_ / "scene.json").string();
    std::string msg = error_of(text);
    EXPECT_TRUE(contains(msg, path + ": " + pointer + ": ")) << "input:\n" << text;
    EXPECT_TRUE(contains(msg, fragment)) << "input:\n" << text;
  }

  // A scene whose only shape is `shape`; `rest` holds other top-level members,
  // each followed by a comma.
  static std::string with_shape(const std::string& shape, const std::string& rest = "") {
    return "{" + rest + "\"shapes\": [" + shape + "]}";
  }

  fs::path dir_;
};

// ---------------------------------------------------------------- shipped scenes

TEST(ShippedScenes, CornellSpheres) {
  LoadedScene loaded = load_scene((kScenes / "cornell_spheres.json").string());
  const Scene& s = loaded.scene;
  EXPECT_TRUE(loaded.warnings.empty());
  // Five walls and the light's emitting quad, two triangles each, and two spheres.
  EXPECT_EQ(s.triangle_count(), 12u);
  EXPECT_EQ(s.primitives.size(), 14u);
  int spheres = 0;
  for (const auto& p : s.primitives) spheres += dynamic_cast<const Sphere*>(p.get()) != nullptr;
  EXPECT_EQ(spheres, 2);
  ASSERT_EQ(s.lights.size(), 1u);
  const auto* light = dynamic_cast<const AreaLight*>(s.lights[0].get());
  ASSERT_NE(light, nullptr);
  EXPECT_NEAR(glm::length(light->direction - Vec3(0, -1, 0)), 0.0, 1e-12) << "the light faces down";
  EXPECT_NEAR(light->area(), 0.0625, 1e-12);
  EXPECT_LT(light->position.y, 1.0) << "just below the ceiling";

  EXPECT_NEAR(glm::length(s.camera.pos - Vec3(0, 0.5, 2.1)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(s.camera.c2w[2] - Vec3(0, 0, 1)), 0.0, 1e-12) << "looks down -z into the box";
  EXPECT_DOUBLE_EQ(s.camera.vfov, 32.0);
  ASSERT_NE(s.bvh, nullptr);
  BBox b = s.bounds();
  EXPECT_NEAR(glm::length(b.min - Vec3(-0.5, 0, -0.5)), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(b.max - Vec3(0.5, 1, 0.5)), 0.0, 1e-9);

  // Every wall faces into the box: its normal points at the box centre.
  for (const auto& m : s.meshes) {
    Vec3 c = (m->positions[0] + m->positions[2]) * 0.5;
    EXPECT_GT(glm::dot(m->normals[0], Vec3(0, 0.5, 0) - c), 0.0) << "quad at " << c;
  }
}

TEST(ShippedScenes, CornellBunny) {
  LoadedScene loaded = load_scene((kScenes / "cornell_bunny.json").string());
  const Scene& s = loaded.scene;
  EXPECT_TRUE(loaded.warnings.empty());
  EXPECT_EQ(s.triangle_count(), 12u + 3674u);
  EXPECT_EQ(s.primitives.size(), 12u + 3674u);
  ASSERT_EQ(s.meshes.size(), 7u);
  const Mesh& bunny = *s.meshes.back();
  EXPECT_EQ(bunny.faces.size(), 3674u);
  EXPECT_EQ(bunny.positions.size(), 1839u);
  ASSERT_EQ(bunny.normals.size(), bunny.positions.size()) << "normals computed for an OBJ without them";
  for (const Vec3& n : bunny.normals) ASSERT_NEAR(glm::length(n), 1.0, 1e-9);
  BBox box;
  for (const Vec3& p : bunny.positions) box.expand(p);
  EXPECT_NEAR(box.min.y, 0.0, 1e-3) << "sits on the floor";
  EXPECT_GT(box.min.x, -0.5);
  EXPECT_LT(box.max.x, 0.5);
  EXPECT_GT(box.min.z, -0.5);
  EXPECT_LT(box.max.z, 0.5);
  EXPECT_LT(box.max.y, 0.99) << "below the light";
  EXPECT_EQ(count_lights<AreaLight>(s), 1);
}

TEST(ShippedScenes, TestScenesHaveOneLightEach) {
  struct Case {
    const char* file;
    int area, point, directional, sky;
  };
  for (const Case& c : {Case{"one_sphere.json", 1, 0, 0, 0}, Case{"point_light.json", 0, 1, 0, 0},
                        Case{"directional_light.json", 0, 0, 1, 0}, Case{"sky.json", 0, 0, 0, 1}}) {
    SCOPED_TRACE(c.file);
    LoadedScene loaded = load_scene((kScenes / "tests" / c.file).string());
    const Scene& s = loaded.scene;
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(count_lights<AreaLight>(s), c.area);
    EXPECT_EQ(count_lights<PointLight>(s), c.point);
    EXPECT_EQ(count_lights<DirectionalLight>(s), c.directional);
    EXPECT_EQ(count_lights<SkyLight>(s), c.sky);
    EXPECT_EQ(s.background(Vec3(0, 1, 0)) != Spectrum(0.0), c.sky == 1);
  }
  // one_sphere: the centre ray from (0, 0, 3) hits the unit sphere at t = 2.
  LoadedScene one = load_scene((kScenes / "tests" / "one_sphere.json").string());
  Intersection isect;
  Ray r(one.scene.camera.pos, -one.scene.camera.c2w[2]);
  ASSERT_TRUE(one.scene.intersect(r, &isect));
  EXPECT_NEAR(isect.t, 2.0, 1e-9);
}

// Whatever scene is added later to scenes/ or scenes/tests/ must load too,
// without warnings. (Other folders may hold JSON that is not a scene, and so
// does scenes/library.json, the scene library's manifest.)
TEST(ShippedScenes, EveryJsonSceneLoadsWithoutWarnings) {
  int n = 0;
  for (const fs::path& dir : {kScenes, kScenes / "tests"}) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().extension() != ".json" || entry.path().filename() == "library.json") continue;
      SCOPED_TRACE(entry.path().string());
      ++n;
      LoadedScene loaded;
      EXPECT_NO_THROW(loaded = load_scene(entry.path().string()));
      for (const auto& w : loaded.warnings) ADD_FAILURE() << "warning: " << w;
      EXPECT_FALSE(loaded.scene.primitives.empty());
      EXPECT_NE(loaded.scene.bvh, nullptr);
    }
  }
  EXPECT_GE(n, 6);
}

// ---------------------------------------------------------------- defaults, cameras

TEST_F(SceneFiles, DefaultsForEverythingLeftOut) {
  LoadedScene loaded = load_scene(write("min.json", kMinimal));
  const Scene& s = loaded.scene;
  EXPECT_TRUE(loaded.warnings.empty());
  EXPECT_TRUE(s.lights.empty());
  ASSERT_EQ(s.primitives.size(), 1u);
  const auto* bsdf = dynamic_cast<const DiffuseBSDF*>(s.primitives[0]->get_bsdf());
  ASSERT_NE(bsdf, nullptr) << "a shape without a material is grey diffuse";
  EXPECT_EQ(bsdf->reflectance, Spectrum(0.5));
  // The default camera: at the origin looking down -z, vfov 35, hfov for 4:3.
  EXPECT_EQ(s.camera.pos, Vec3(0.0));
  EXPECT_NEAR(glm::length(s.camera.c2w[2] - Vec3(0, 0, 1)), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.camera.vfov, 35.0);
  double expected_hfov = glm::degrees(2.0 * std::atan(4.0 / 3.0 * std::tan(glm::radians(35.0) / 2.0)));
  EXPECT_NEAR(s.camera.hfov, expected_hfov, 1e-9);
  EXPECT_DOUBLE_EQ(s.camera.near_clip, 1e-4);
  EXPECT_DOUBLE_EQ(s.camera.far_clip, 1e30);
}

TEST_F(SceneFiles, LightsAndMaterialsAsWritten) {
  LoadedScene loaded = load_scene(write("s.json", R"({
    "materials": {"lamp": {"type": "emission", "radiance": [2, 3, 4]},
                  "red": {"type": "diffuse", "albedo": [0.9, 0.1, 0.0]}},
    "lights": [
      {"type": "area", "radiance": [1, 2, 3], "center": [0, 5, 0], "edge_x": [2, 0, 0], "edge_y": [0, 0, 3]},
      {"type": "point", "intensity": [7, 8, 9], "position": [1, 2, 3]},
      {"type": "directional", "direction": [0, -2, 0]},
      {"type": "sky", "radiance": [0.5, 0.5, 0.5]}
    ],
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"}]})"));
  const Scene& s = loaded.scene;
  ASSERT_EQ(s.lights.size(), 4u);
  const auto* area = dynamic_cast<const AreaLight*>(s.lights[0].get());
  ASSERT_NE(area, nullptr);
  EXPECT_EQ(area->radiance, Spectrum(1, 2, 3));
  EXPECT_NEAR(glm::length(area->direction - Vec3(0, -1, 0)), 0.0, 1e-12) << "normalize(cross(edge_x, edge_y))";
  EXPECT_NEAR(area->area(), 6.0, 1e-12);
  const auto* point = dynamic_cast<const PointLight*>(s.lights[1].get());
  ASSERT_NE(point, nullptr);
  EXPECT_EQ(point->intensity, Spectrum(7, 8, 9));
  EXPECT_EQ(point->position, Vec3(1, 2, 3));
  const auto* sun = dynamic_cast<const DirectionalLight*>(s.lights[2].get());
  ASSERT_NE(sun, nullptr);
  EXPECT_EQ(sun->radiance, Spectrum(1.0)) << "default radiance";
  EXPECT_NEAR(glm::length(sun->direction - Vec3(0, -1, 0)), 0.0, 1e-12);
  EXPECT_EQ(s.background(Vec3(1, 0, 0)), Spectrum(0.5));
  // The area light's quad is visible and emits downwards.
  EXPECT_EQ(s.primitives.size(), 3u);
  const auto* red = dynamic_cast<const DiffuseBSDF*>(s.primitives.back()->get_bsdf());
  ASSERT_NE(red, nullptr);
  EXPECT_EQ(red->reflectance, Spectrum(0.9, 0.1, 0.0));
  EXPECT_TRUE(loaded.warnings.empty()) << "the lamp material is defined but used by no shape";
}

TEST_F(SceneFiles, EmittingShapeThatIsNotALightIsAWarning) {
  LoadedScene loaded = load_scene(write("s.json", R"({
    "materials": {"lamp": {"type": "emission", "radiance": [2, 2, 2]}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "lamp"}]})"));
  ASSERT_EQ(loaded.warnings.size(), 1u);
  EXPECT_TRUE(contains(loaded.warnings[0], "/shapes/0"));
  EXPECT_TRUE(contains(loaded.warnings[0], "lamp"));
}

TEST_F(SceneFiles, CameraFile) {
  Camera c = load_camera(write("cam.json", R"({"position": [1, 2, 3], "target": [1, 2, 0], "up": [1, 0, 0],
                                              "vfov": 30, "hfov": 60, "near": 0.5, "far": 100})"));
  EXPECT_EQ(c.pos, Vec3(1, 2, 3));
  EXPECT_DOUBLE_EQ(c.vfov, 30.0);
  EXPECT_DOUBLE_EQ(c.hfov, 60.0);
  EXPECT_DOUBLE_EQ(c.near_clip, 0.5);
  EXPECT_DOUBLE_EQ(c.far_clip, 100.0);
  EXPECT_NEAR(glm::length(c.c2w[2] - Vec3(0, 0, 1)), 0.0, 1e-12) << "backward axis";
  EXPECT_NEAR(glm::length(c.c2w[1] - Vec3(1, 0, 0)), 0.0, 1e-12) << "the given up";
  // up (0, 0, 1) is parallel to the view: refused with its place.
  std::string path = write("bad.json", R"({"position": [0, 0, 0], "target": [0, 0, -1], "up": [0, 0, 1]})");
  try {
    load_camera(path);
    ADD_FAILURE() << "loaded";
  } catch (const SceneError& e) {
    EXPECT_TRUE(contains(e.what(), path + ": /up: "));
  }
  path = write("bad2.json", R"({"camera": {"position": [0, 0, 0]}})");
  try {
    load_camera(path);
    ADD_FAILURE() << "a camera file holds the camera's fields, not a scene";
  } catch (const SceneError& e) {
    EXPECT_TRUE(contains(e.what(), path + ": /camera: unknown key"));
  }
  EXPECT_THROW(load_camera((dir_ / "none.json").string()), SceneError);
}

// ---------------------------------------------------------------- meshes and transforms

// One right triangle in the z = 0 plane, normals given per vertex.
const char* kTriangleObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    "vn 0 0 1\n"
    "f 1//1 2//1 3//1\n";

TEST_F(SceneFiles, MeshTransformScalesThenRotatesThenTranslates) {
  write("meshes/tri.obj", kTriangleObj);
  // Scale x by 2, rotate 90 degrees about +z (x -> y), move by (0, 0, 5).
  LoadedScene loaded = load_scene(write("s.json", with_shape(R"({"type": "mesh", "file": "meshes/tri.obj",
      "transform": {"scale": [2, 1, 1], "rotate": {"axis": [0, 0, 1], "degrees": 90}, "translate": [0, 0, 5]}})")));
  ASSERT_EQ(loaded.scene.meshes.size(), 1u);
  const Mesh& m = *loaded.scene.meshes[0];
  ASSERT_EQ(m.positions.size(), 3u);
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_NEAR(glm::length(m.positions[m.faces[0][0]] - Vec3(0, 0, 5)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(m.positions[m.faces[0][1]] - Vec3(0, 2, 5)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(m.positions[m.faces[0][2]] - Vec3(-1, 0, 5)), 0.0, 1e-12);
  for (const Vec3& n : m.normals) EXPECT_NEAR(glm::length(n - Vec3(0, 0, 1)), 0.0, 1e-12);
  EXPECT_TRUE(loaded.warnings.empty());
}

TEST_F(SceneFiles, NormalsStayPerpendicularUnderNonUniformScale) {
  // A face tilted 45 degrees about the y axis, with its exact normal.
  write("tilted.obj",
        "v 0 0 0\nv 1 0 1\nv 0 1 0\n"
        "vn -0.70710678118654752 0 0.70710678118654752\n"
        "f 1//1 2//1 3//1\n");
  LoadedScene loaded = load_scene(write("s.json", with_shape(R"({"type": "mesh", "file": "tilted.obj",
      "transform": {"scale": [3, 1, 0.5], "rotate": {"axis": [1, 1, 0], "degrees": 33}, "translate": [1, 2, 3]}})")));
  const Mesh& m = *loaded.scene.meshes[0];
  Vec3 e1 = m.positions[m.faces[0][1]] - m.positions[m.faces[0][0]];
  Vec3 e2 = m.positions[m.faces[0][2]] - m.positions[m.faces[0][0]];
  Vec3 face_n = glm::normalize(glm::cross(e1, e2));
  for (const Vec3& n : m.normals) {
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(n, face_n), 1.0, 1e-9) << "normal " << n << " face " << face_n;
  }
}

TEST_F(SceneFiles, UniformScaleAsOneNumberAndComputedNormals) {
  // No normals in the file: the loader computes them from the faces. A quad
  // is triangulated into two triangles.
  write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 4 3 2\n");
  LoadedScene loaded = load_scene(write("s.json", with_shape(R"({"type": "mesh", "file": "quad.obj",
      "transform": {"scale": 3}})")));
  const Mesh& m = *loaded.scene.meshes[0];
  EXPECT_EQ(m.faces.size(), 2u);
  BBox box;
  for (const Vec3& p : m.positions) box.expand(p);
  EXPECT_NEAR(glm::length(box.max - Vec3(3, 0, 3)), 0.0, 1e-12);
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const Vec3& n : m.normals) EXPECT_NEAR(glm::length(n - Vec3(0, 1, 0)), 0.0, 1e-12);
}

TEST_F(SceneFiles, ObjNormalsAreKeptOnlyWhenEveryCornerHasOne) {
  // Deliberately "smooth" normals that differ from the face normal: kept.
  write("smooth.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 1\nvn 0 1 1\nvn 0 0 1\nf 1//1 2//2 3//3\n");
  LoadedScene smooth = load_scene(write("a.json", with_shape(R"({"type": "mesh", "file": "smooth.obj"})")));
  const Mesh& kept = *smooth.scene.meshes[0];
  Vec3 expected = glm::normalize(Vec3(1, 0, 1));
  EXPECT_NEAR(glm::length(kept.normals[kept.faces[0][0]] - expected), 0.0, 1e-12);

  // One corner without a normal: all are computed from the face.
  write("partial.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 1\nf 1//1 2//1 3\n");
  LoadedScene partial = load_scene(write("b.json", with_shape(R"({"type": "mesh", "file": "partial.obj"})")));
  for (const Vec3& n : partial.scene.meshes[0]->normals) EXPECT_NEAR(glm::length(n - Vec3(0, 0, 1)), 0.0, 1e-12);
}

TEST_F(SceneFiles, ACreaseKeepsBothNormals) {
  // Two faces share vertices 1 and 3 but give them different normals.
  write("crease.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 1 0 0\n"
        "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n");
  LoadedScene loaded = load_scene(write("s.json", with_shape(R"({"type": "mesh", "file": "crease.obj"})")));
  const Mesh& m = *loaded.scene.meshes[0];
  ASSERT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(m.positions.size(), 6u) << "vertices split where normals differ";
  for (uint32_t i : m.faces[0]) EXPECT_EQ(m.normals[i], Vec3(0, 0, 1));
  for (uint32_t i : m.faces[1]) EXPECT_EQ(m.normals[i], Vec3(1, 0, 0));
}

TEST_F(SceneFiles, ObjMaterialsLinesAndPointsAreWarnedAbout) {
  write("m.obj", std::string("mtllib m.mtl\nusemtl shiny\n") + kTriangleObj + "l 1 2\n");
  LoadedScene loaded = load_scene(write("s.json", with_shape(R"({"type": "mesh", "file": "m.obj"})")));
  ASSERT_EQ(loaded.warnings.size(), 2u);
  for (const auto& w : loaded.warnings) {
    EXPECT_TRUE(contains(w, "/shapes/0: "));
    EXPECT_TRUE(contains(w, "m.obj"));
  }
  EXPECT_TRUE(contains(loaded.warnings[0] + loaded.warnings[1], "materials"));
  EXPECT_TRUE(contains(loaded.warnings[0] + loaded.warnings[1], "line"));
  EXPECT_EQ(loaded.scene.triangle_count(), 1u);

  // Faces of two vertices are skipped, and said so once.
  write("short.obj", std::string(kTriangleObj) + "f 1 2\nf 2 3\n");
  LoadedScene short_faces = load_scene(write("t.json", with_shape(R"({"type": "mesh", "file": "short.obj"})")));
  ASSERT_EQ(short_faces.warnings.size(), 1u);
  EXPECT_TRUE(contains(short_faces.warnings[0], "fewer than 3 vertices skipped (2 times)"));
}

TEST_F(SceneFiles, BadMeshFiles) {
  expect_content_error(with_shape(R"({"type": "mesh", "file": "meshes/nope.obj"})"), "/shapes/0/file",
                       (dir_ / "meshes" / "nope.obj").string() + ": cannot open: no such file");

  write("zero_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  std::string msg = error_of(with_shape(R"({"type": "mesh", "file": "zero_index.obj"})"));
  EXPECT_TRUE(contains(msg, ": /shapes/0/file: "));
  EXPECT_TRUE(contains(msg, (dir_ / "zero_index.obj").string() + ":4: vertex index 0"));

  write("empty.obj", "# nothing but vertices\nv 0 0 0\nv 1 0 0\n");
  msg = error_of(with_shape(R"({"type": "mesh", "file": "empty.obj"})"));
  EXPECT_TRUE(contains(msg, ": /shapes/0/file: "));
  EXPECT_TRUE(contains(msg, "empty.obj: no triangles"));

  write("garbage.obj", "this is not an OBJ file\n\x01\x02\x03\n");
  EXPECT_TRUE(contains(error_of(with_shape(R"({"type": "mesh", "file": "garbage.obj"})")), "garbage.obj: no triangles"));

  write("past_end.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  msg = error_of(with_shape(R"({"type": "mesh", "file": "past_end.obj"})"));
  EXPECT_TRUE(contains(msg, "past_end.obj:4: a face refers to vertex 4, but the file has 3"));

  write("past_end_quad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 9\n");
  EXPECT_TRUE(contains(error_of(with_shape(R"({"type": "mesh", "file": "past_end_quad.obj"})")),
                       "past_end_quad.obj:5: a face refers to vertex 9, but the file has 4"));

  write("bad_normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n");
  EXPECT_TRUE(contains(error_of(with_shape(R"({"type": "mesh", "file": "bad_normal.obj"})")),
                       "bad_normal.obj: normal 1 is zero"));

  write("dir.obj/x", "");
  expect_content_error(with_shape(R"({"type": "mesh", "file": "dir.obj"})"), "/shapes/0/file",
                       "dir.obj: is a directory, not a mesh file");
}

// The OBJ pre-check (obj_text_check.h) refuses what tinyobjloader would
// misread, at its line; it must let through every form tinyobjloader reads in
// full, or good files would be refused.
TEST_F(SceneFiles, ObjCheckAcceptsEveryFormTinyobjReads) {
  write("forms.obj",
        "# a comment line, then numbers in every decimal form\r\n"
        "v .5 -1. +2e-3\r\n"
        "v 1E+2 0 0 # a comment after the values\n"
        "v 0 1 0 0.2 0.4 0.6\r"
        "v 0 0 1\n"
        "vt 0.5 0.5\nvn 0 0 1\n"
        "f 1/1/1 2/1/1 3/1/1\n"
        "f -4//-1 -3//-1 -1//-1\n"
        "f 1 2 3 4\n"
        "f 5 6 7\n"  // refers to vertices defined below (legal in OBJ)
        "v 0 0 2\nv 1 0 2\nv 0 1 2\n");
  LoadedScene loaded = load_scene(write("s.json", with_shape(R"({"type": "mesh", "file": "forms.obj"})")));
  EXPECT_EQ(loaded.scene.triangle_count(), 5u) << "a triangle, a triangle, a quad, a triangle";
}

TEST_F(SceneFiles, ObjCheckCountsLinesLikeTinyobj) {
  // \r\n and a lone \r each end one line: the NaN is on line 4.
  write("lines.obj", "v 0 0 0\r\nv 1 0 0\rv 0 1 0\nv nan 0 0\nf 1 2 3\n");
  EXPECT_TRUE(contains(error_of(with_shape(R"({"type": "mesh", "file": "lines.obj"})")),
                       "lines.obj:4: vertex value \"nan\" is not a decimal number"));
}

TEST_F(SceneFiles, NulBytesAreRefused) {
  std::string path = (dir_ / "scene.json").string();
  const char text[] = "{\"shapes\": []}\n\0trailing";
  EXPECT_TRUE(contains(error_of(std::string(text, sizeof text - 1)), path + ":2:1: a NUL byte"));
  write("tri.obj", kTriangleObj);
  expect_content_error(with_shape(R"({"type": "mesh", "file": "tri.obj\u0000.png"})"), "/shapes/0/file",
                       "a string may not contain the NUL character");
}

// ---------------------------------------------------------------- syntax errors

TEST_F(SceneFiles, SyntaxErrorsGiveLineAndColumn) {
  std::string path = (dir_ / "scene.json").string();
  // A doubled comma: the second one, line 3 column 36, cannot start a key.
  EXPECT_TRUE(contains(error_of("{\n  \"shapes\": [\n    {\"type\": \"sphere\", \"radius\": 1,, \"center\": [0, 0, 0]}\n  ]\n}"),
                       path + ":3:36: syntax error"));
  // NaN and Infinity are not JSON: refused at the character that gives them
  // away ("N"; "I" after the minus sign).
  EXPECT_TRUE(contains(error_of("{\"shapes\": [{\"type\": \"sphere\", \"radius\": NaN}]}"), path + ":1:42: "));
  EXPECT_TRUE(contains(error_of("{\"shapes\": [\n{\"radius\": -Infinity}]}"), path + ":2:13: "));
  // Cut short: the error is at the end of the text.
  EXPECT_TRUE(contains(error_of("{\"shapes\": [\n"), path + ":2:1: "));
  EXPECT_TRUE(contains(error_of(""), path + ":1:1: "));
  // Text after the document.
  EXPECT_TRUE(contains(error_of(std::string(kMinimal) + "\n}"), path + ":2:1: "));
}

TEST_F(SceneFiles, NumbersTooLargeForADoubleAreSyntaxErrorsAtTheNumber) {
  std::string path = (dir_ / "scene.json").string();
  std::string msg = error_of("{\"shapes\": [{\"type\": \"sphere\",\n  \"radius\": 1e999}]}");
  EXPECT_TRUE(contains(msg, path + ":2:13: ")) << "the column where 1e999 starts";
  EXPECT_TRUE(contains(msg, "1e999"));
  EXPECT_TRUE(contains(error_of("{\"shapes\": [{\"center\": [0, -2e400, 0]}]}"), path + ":1:28: "));
}

TEST_F(SceneFiles, DuplicateKeysAreRefused) {
  expect_content_error(with_shape(R"({"type": "sphere", "radius": 1, "center": [0, 0, 0], "radius": 2})"),
                       "/shapes/0/radius", "duplicate key");
  expect_content_error(R"({"materials": {"a": {"type": "diffuse"}, "a": {"type": "diffuse"}}, "shapes": []})",
                       "/materials/a", "duplicate key");
}

// ---------------------------------------------------------------- content errors

TEST_F(SceneFiles, MissingOrUnusableFiles) {
  std::string missing = (dir_ / "missing.json").string();
  try {
    load_scene(missing);
    ADD_FAILURE() << "loaded a missing file";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open: no such file");
  }
  write("dir.json/inside", "");
  try {
    load_scene(dir_.string() + "/dir.json");
    ADD_FAILURE() << "loaded a directory";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), dir_.string() + "/dir.json: is a directory, not a scene file");
  }
  EXPECT_TRUE(contains(error_of(kMinimal, "scene.obj"), "unknown scene format \".obj\" (expected .json or .dae)"));
}

TEST_F(SceneFiles, StructureErrors) {
  expect_content_error("[1, 2]", "/", "expected an object, got an array");
  expect_content_error(R"({"shape": []})", "/shape", "unknown key \"shape\"");
  expect_content_error(R"({"camera": {}})", "/", "missing required field \"shapes\"");
  expect_content_error(R"({"shapes": []})", "/shapes", "a scene needs at least one shape");
  expect_content_error(R"({"shapes": {}})", "/shapes", "expected an array, got an object");
  expect_content_error(with_shape("1"), "/shapes/0", "expected an object");
  expect_content_error(with_shape("{}"), "/shapes/0", "missing required field \"type\"");
  expect_content_error(with_shape(R"({"type": 3})"), "/shapes/0/type", "expected a string, got a number");
  expect_content_error(with_shape(R"({"type": "cube"})"), "/shapes/0/type", "unknown type \"cube\"");
  expect_content_error(R"({"description": 1, "shapes": []})", "/description", "expected a string");
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})", R"("lights": {},)"),
                       "/lights", "expected an array");
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})",
                                  R"("lights": [{"type": "spot"}],)"),
                       "/lights/0/type", "unknown type \"spot\"");
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})",
                                  R"("materials": [],)"),
                       "/materials", "expected an object");
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})",
                                  R"("materials": {"m": {"type": "glass"}},)"),
                       "/materials/m/type", "unknown type \"glass\"");
}

TEST_F(SceneFiles, UnknownKeysAreNamed) {
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "raduis": 1})"), "/shapes/0/raduis",
                       "unknown key \"raduis\" (allowed here: type, center, radius, material)");
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})",
                                  R"("materials": {"m": {"type": "diffuse", "color": [1, 0, 0]}},)"),
                       "/materials/m/color", "unknown key");
  // A key valid for another type is still unknown here.
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "edge_x": [1, 0, 0]})"),
                       "/shapes/0/edge_x", "unknown key");
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})",
                                  R"("camera": {"fov": 40},)"),
                       "/camera/fov", "unknown key");
}

TEST_F(SceneFiles, WrongTypesLengthsAndRanges) {
  auto sphere = [](const std::string& center, const std::string& radius) {
    return with_shape(R"({"type": "sphere", "center": )" + center + R"(, "radius": )" + radius + "}");
  };
  expect_content_error(sphere("[0, 0, 0]", "\"1\""), "/shapes/0/radius", "expected a positive number, got a string");
  expect_content_error(sphere("[0, 0, 0]", "-1"), "/shapes/0/radius", "expected a positive number, got -1");
  expect_content_error(sphere("[0, 0, 0]", "0"), "/shapes/0/radius", "expected a positive number, got 0");
  expect_content_error(sphere("[0, 0, 0]", "1e300"), "/shapes/0/radius", "at most 1e30");
  expect_content_error(sphere("[0, 0, 0]", "true"), "/shapes/0/radius", "got a boolean");
  expect_content_error(sphere("[0, 0, 0]", "null"), "/shapes/0/radius", "got null");
  expect_content_error(sphere("[0, 0]", "1"), "/shapes/0/center", "expected an array of 3 numbers, got 2 elements");
  expect_content_error(sphere("[0, 0, 0, 0]", "1"), "/shapes/0/center", "got 4 elements");
  expect_content_error(sphere("0", "1"), "/shapes/0/center", "expected an array of 3 numbers, got a number");
  expect_content_error(sphere("[0, \"0\", 0]", "1"), "/shapes/0/center/1", "expected a finite number, got a string");
  expect_content_error(sphere("[0, 0, -1e31]", "1"), "/shapes/0/center/2", "at most 1e30");
  expect_content_error(with_shape(R"({"type": "sphere", "radius": 1})"), "/shapes/0",
                       "missing required field \"center\"");

  const std::string ball = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";
  expect_content_error(with_shape(ball, R"("materials": {"w": {"type": "diffuse", "albedo": [1.5, 0, 0]}},)"),
                       "/materials/w/albedo/0", "expected a number in [0, 1], got 1.5");
  expect_content_error(with_shape(ball, R"("materials": {"a/b": {"type": "diffuse", "albedo": [0, -0.1, 0]}},)"),
                       "/materials/a~1b/albedo/1", "expected a number in [0, 1]");
  expect_content_error(with_shape(ball, R"("lights": [{"type": "sky", "radiance": [1, 1, -1]}],)"),
                       "/lights/0/radiance/2", "expected a non-negative number, got -1");
  expect_content_error(with_shape(ball, R"("lights": [{"type": "point", "intensity": [1, 1, 1]}],)"),
                       "/lights/0", "missing required field \"position\"");
  expect_content_error(with_shape(ball, R"("lights": [{"type": "directional", "direction": [0, 0, 0]}],)"),
                       "/lights/0/direction", "expected a non-zero vector");
  expect_content_error(with_shape(ball, R"("lights": [{"type": "area", "center": [0, 0, 0],
                                            "edge_x": [1, 0, 0], "edge_y": [2, 0, 0]}],)"),
                       "/lights/0/edge_y", "must not be parallel to edge_x");
  expect_content_error(with_shape(R"({"type": "quad", "center": [0, 0, 0], "edge_x": [0, 0, 0], "edge_y": [1, 0, 0]})"),
                       "/shapes/0/edge_x", "expected a non-zero vector");
  expect_content_error(with_shape(R"({"type": "quad", "center": [0, 0, 0], "edge_x": [1, 0, 0]})"), "/shapes/0",
                       "missing required field \"edge_y\"");
}

TEST_F(SceneFiles, UnknownMaterial) {
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "whte"})",
                                  R"("materials": {"white": {"type": "diffuse"}, "red": {"type": "diffuse"}},)"),
                       "/shapes/0/material", "unknown material \"whte\" (defined: red, white)");
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "x"})"),
                       "/shapes/0/material", "no materials are defined");
  expect_content_error(with_shape(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": 1})"),
                       "/shapes/0/material", "expected a string");
}

TEST_F(SceneFiles, CameraErrors) {
  auto with_camera = [&](const std::string& camera) { return std::string("{\"camera\": ") + camera + ", " +
                                                             std::string(kMinimal).substr(1); };
  expect_content_error(with_camera(R"({"vfov": 180})"), "/camera/vfov", "expected an angle in (0, 180) degrees");
  expect_content_error(with_camera(R"({"vfov": 0})"), "/camera/vfov", "expected a positive number");
  expect_content_error(with_camera(R"({"hfov": -10})"), "/camera/hfov", "expected a positive number");
  expect_content_error(with_camera(R"({"position": [1, 1, 1], "target": [1, 1, 1]})"), "/camera/target",
                       "must differ from the camera position");
  expect_content_error(with_camera(R"({"target": [0, 5, 0]})"), "/camera/up", "parallel to the viewing direction");
  expect_content_error(with_camera(R"({"up": [0, 0, 0]})"), "/camera/up", "expected a non-zero vector");
  expect_content_error(with_camera(R"({"near": 2, "far": 1})"), "/camera/far", "must be greater than near");
  expect_content_error(with_camera(R"({"near": 0})"), "/camera/near", "expected a positive number");
  expect_content_error(with_camera("[]"), "/camera", "expected an object");
}

TEST_F(SceneFiles, TransformErrors) {
  write("tri.obj", kTriangleObj);
  auto mesh = [](const std::string& transform) {
    return with_shape(R"({"type": "mesh", "file": "tri.obj", "transform": )" + transform + "}");
  };
  expect_content_error(mesh(R"({"rotation": {}})"), "/shapes/0/transform/rotation",
                       "unknown key \"rotation\" (allowed here: scale, rotate, translate)");
  expect_content_error(mesh(R"({"scale": -1})"), "/shapes/0/transform/scale", "expected a positive number");
  expect_content_error(mesh(R"({"scale": [1, 0, 1]})"), "/shapes/0/transform/scale/1", "expected a positive number");
  expect_content_error(mesh(R"({"scale": "big"})"), "/shapes/0/transform/scale", "got a string");
  expect_content_error(mesh(R"({"rotate": {"axis": [0, 1, 0]}})"), "/shapes/0/transform/rotate",
                       "missing required field \"degrees\"");
  expect_content_error(mesh(R"({"rotate": {"axis": [0, 0, 0], "degrees": 10}})"),
                       "/shapes/0/transform/rotate/axis", "expected a non-zero vector");
  expect_content_error(mesh(R"({"translate": [1, 2]})"), "/shapes/0/transform/translate", "got 2 elements");
  expect_content_error(mesh("[]"), "/shapes/0/transform", "expected an object");
  expect_content_error(with_shape(R"({"type": "mesh"})"), "/shapes/0", "missing required field \"file\"");
  expect_content_error(with_shape(R"({"type": "mesh", "file": ["tri.obj"]})"), "/shapes/0/file", "expected a string");
}

}  // namespace
}  // namespace pt
