// COLLADA import of valid files: our own .dae files under data/collada (each
// commented with what it holds and where things must land) and the library
// scenes under scenes/collada. Expected values come from the COLLADA
// definitions and the course's conventions (scenes/README.md), worked by hand
// in the files' comments, never from the loader's output.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "collada_test_files.h"
#include "geometry/sphere.h"
#include "scene/course_camera.h"
#include "io/scene_info.h"
#include "pt_source_dir.h"

namespace pt {
namespace {

LoadedScene load_data(const std::string& name) {
  return load_scene((kColladaData / name).string(), BuildBvh::No);
}

#define EXPECT_VEC_NEAR(a, b, tol) EXPECT_NEAR(glm::length((a) - (b)), 0.0, tol) << #a " = " << (a) << ", expected " << (b)

template <class L>
std::vector<const L*> lights_of(const Scene& s) {
  std::vector<const L*> out;
  for (const auto& l : s.lights)
    if (const auto* p = dynamic_cast<const L*>(l.get())) out.push_back(p);
  return out;
}

std::vector<const Sphere*> spheres_of(const Scene& s) {
  std::vector<const Sphere*> out;
  for (const auto& p : s.primitives)
    if (const auto* sp = dynamic_cast<const Sphere*>(p.get())) out.push_back(sp);
  return out;
}

// The sphere nearest to `centre`.
const Sphere* sphere_at(const Scene& s, const Vec3& centre) {
  const Sphere* best = nullptr;
  for (const Sphere* sp : spheres_of(s))
    if (!best || glm::length(sp->o - centre) < glm::length(best->o - centre)) best = sp;
  return best;
}

const Mesh* mesh_named(const Scene& s, const std::string& name) {
  for (const auto& m : s.meshes)
    if (m->name == name) return m.get();
  return nullptr;
}

// The mesh whose first vertex is `first` (materials.dae places one per node).
const Mesh* mesh_starting_at(const Scene& s, const Vec3& first) {
  for (const auto& m : s.meshes)
    if (!m->positions.empty() && glm::length(m->positions[0] - first) < 1e-9) return m.get();
  return nullptr;
}

double half_tan(double deg) { return std::tan(glm::radians(deg) / 2.0); }
double fov_of(double half_tangent) { return glm::degrees(2.0 * std::atan(half_tangent)); }

// ---------------------------------------------------------------- the scene graph

TEST(ColladaGraph, SceneChoosesTheVisualSceneAndEveryNodeTransformPlacesTheTriangle) {
  LoadedScene loaded = load_data("graph.dae");
  const Scene& s = loaded.scene;
  // Five nodes of "main" instance the triangle; the decoy visual scene is not loaded.
  EXPECT_EQ(s.triangle_count(), 5u);
  for (const auto& t : triangles_of(s)) EXPECT_LT(t[0].x, 99.0) << "a triangle from the decoy visual scene";

  // Row-major <matrix>: a quarter turn about z, then (1, 2, 3).
  EXPECT_TRUE(has_triangle(s, Vec3(1, 2, 3), Vec3(1, 3, 3), Vec3(0, 2, 3)));
  // rotate * translate * scale, in document order (the scale acts first).
  EXPECT_TRUE(has_triangle(s, Vec3(0, 10, 0), Vec3(0, 12, 0), Vec3(-2, 10, 0)));
  // Nested nodes: the child's scale inside the parent's translation.
  EXPECT_TRUE(has_triangle(s, Vec3(0, 10, 0), Vec3(3, 10, 0), Vec3(0, 13, 0)));
  // <instance_node>: the library node's (0, 0, 5) inside (0, 0, -20).
  EXPECT_TRUE(has_triangle(s, Vec3(0, 0, -15), Vec3(1, 0, -15), Vec3(0, 1, -15)));
  // <lookat>: local -z along +x, local x along +z.
  EXPECT_TRUE(has_triangle(s, Vec3(0, 0, 30), Vec3(0, 0, 31), Vec3(0, 1, 30)));
}

// ---------------------------------------------------------------- Z_UP, spheres, the area light, the camera

TEST(ColladaZUp, VerticesAreConvertedAsTheCourseDoes) {
  LoadedScene loaded = load_data("zup.dae");
  // (x, y, z) -> (-x, z, y) after the node's move by (1, 2, 3).
  EXPECT_TRUE(has_triangle(loaded.scene, Vec3(-1, 3, 2), Vec3(-2, 3, 2), Vec3(-1, 3, 3)));
}

TEST(ColladaZUp, SphereCentreIsTheTransformedOriginAndItsRadiusIsScaled) {
  LoadedScene loaded = load_data("zup.dae");
  const Scene& s = loaded.scene;
  ASSERT_EQ(spheres_of(s).size(), 2u);
  const Sphere* scaled = sphere_at(s, Vec3(-1, 3, 2));
  EXPECT_VEC_NEAR(scaled->o, Vec3(-1, 3, 2), 1e-12);
  EXPECT_NEAR(scaled->r, 1.0, 1e-12) << "radius 0.5 under a scale of 2";
  // Scaled along x only: the course's rule takes |T x|; the loader says so.
  const Sphere* squashed = sphere_at(s, Vec3(-5, 0, 0));
  EXPECT_VEC_NEAR(squashed->o, Vec3(-5, 0, 0), 1e-12);
  EXPECT_NEAR(squashed->r, 1.5, 1e-12);
  EXPECT_EQ(count_containing(loaded.warnings, "node[@id='ball-squashed']"), 1u);
  EXPECT_EQ(count_containing(loaded.warnings, "non-uniform scale"), 1u);
  EXPECT_EQ(loaded.warnings.size(), 1u) << "only the squashed sphere is worth a warning";
}

TEST(ColladaZUp, AreaLightEdgesDirectionAndRadianceFollowTheNode) {
  LoadedScene loaded = load_data("zup.dae");
  auto areas = lights_of<AreaLight>(loaded.scene);
  ASSERT_EQ(areas.size(), 1u) << "the CGL area wins over technique_common's point";
  EXPECT_EQ(loaded.scene.lights.size(), 1u);
  const AreaLight* a = areas[0];
  EXPECT_VEC_NEAR(a->position, Vec3(0, 4, 0), 1e-12);
  EXPECT_VEC_NEAR(a->dim_x, Vec3(0.8, 0, 0), 1e-12) << "T(cross(up, direction)) = T(-x)";
  EXPECT_VEC_NEAR(a->dim_y, Vec3(0, 0, 0.6), 1e-12) << "T(up) = T(y)";
  EXPECT_VEC_NEAR(a->direction, Vec3(0, -1, 0), 1e-12) << "emits along T(-z): down";
  EXPECT_NEAR(a->area(), 0.48, 1e-12);
  EXPECT_VEC_NEAR(a->radiance, Spectrum(4, 5, 6), 0.0);
}

TEST(ColladaZUp, TheEmissiveQuadIsKeptAsDrawnBesideTheLight) {
  // The course's Cornell boxes draw the lamp turned by 90 degrees from the
  // light they sample; both stay as the file says.
  LoadedScene loaded = load_data("zup.dae");
  const Mesh* quad = mesh_named(loaded.scene, "lamp-quad");
  ASSERT_NE(quad, nullptr);
  BBox b;
  for (const Vec3& p : quad->positions) b.expand(p);
  EXPECT_NEAR(b.extent().x, 0.6, 1e-12);
  EXPECT_NEAR(b.extent().z, 0.8, 1e-12);
  EXPECT_NEAR(b.min.y, 4.01, 1e-12);
  const auto* emission = dynamic_cast<const EmissionBSDF*>(quad->bsdf);
  ASSERT_NE(emission, nullptr);
  EXPECT_VEC_NEAR(emission->radiance, Spectrum(4, 5, 6), 0.0);
  // It has no normals in the file: they are computed, facing down like the light.
  ASSERT_EQ(quad->normals.size(), quad->positions.size());
  for (const Vec3& n : quad->normals) EXPECT_VEC_NEAR(n, Vec3(0, -1, 0), 1e-12);
}

TEST(ColladaZUp, TheFileCameraIsPlacedByItsNode) {
  LoadedScene loaded = load_data("zup.dae");
  const Camera& c = loaded.scene.camera;
  EXPECT_VEC_NEAR(c.pos, Vec3(0, 1, 4.9), 1e-12);
  EXPECT_VEC_NEAR(-c.c2w[2], Vec3(0, 0, -1), 1e-12) << "Blender's -y view becomes -z";
  EXPECT_VEC_NEAR(c.c2w[1], Vec3(0, 1, 0), 1e-12) << "Blender's z up becomes y";
  EXPECT_NEAR(c.hfov, 49.13434, 1e-9);
  EXPECT_NEAR(c.vfov, fov_of(half_tan(49.13434) / 1.777778), 1e-9) << "from xfov and aspect_ratio";
  EXPECT_DOUBLE_EQ(c.near_clip, 0.1);
  EXPECT_DOUBLE_EQ(c.far_clip, 100.0);
}

class ColladaAxes : public DaeFiles {};

TEST_F(ColladaAxes, XUpAndYUpAndTheDefault) {
  // X_UP as the course's loader converts it: (x, y, z) -> (y, x, -z), a rotation.
  LoadedScene x_up = load(collada_document("", kTriNode, "X_UP"));
  EXPECT_TRUE(has_triangle(x_up.scene, Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)));
  LoadedScene y_up = load(collada_document("", kTriNode, "Y_UP"));
  EXPECT_TRUE(has_triangle(y_up.scene, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
  // Without <up_axis>, COLLADA's default Y_UP.
  std::string none = collada_document("", kTriNode);
  none.replace(none.find("<up_axis>"), std::string("<up_axis>Y_UP</up_axis>").size(), "");
  EXPECT_TRUE(has_triangle(load(none).scene, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
}

TEST_F(ColladaAxes, FileNormalsFollowTheInverseTranspose) {
  // A normal (1, 1, 0) under a scale of 2 along y: the surface it is normal
  // to is stretched, so the normal turns towards x: (1, 1/2, 0), normalised.
  std::string g = geometry(R"(<source id="g-pos"><float_array id="g-arr">0 0 0  1 -1 0  0 0 1</float_array></source>
    <source id="g-n"><float_array id="g-n-arr">1 1 0</float_array></source>
    <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#g-v" offset="0"/><input semantic="NORMAL" source="#g-n" offset="1"/>
      <p>0 0 1 0 2 0</p></triangles>)");
  LoadedScene loaded = load(collada_document(g, R"(<node id="n"><scale>1 2 1</scale><instance_geometry url="#g"/></node>)"));
  const Mesh* m = mesh_named(loaded.scene, "g");
  ASSERT_NE(m, nullptr);
  ASSERT_EQ(m->normals.size(), 3u);
  for (const Vec3& n : m->normals) EXPECT_VEC_NEAR(n, glm::normalize(Vec3(1, 0.5, 0)), 1e-12);
}

// ---------------------------------------------------------------- meshes

TEST(ColladaMeshes, PolylistOffsetsAndConcavePolygons) {
  LoadedScene loaded = load_data("meshes.dae");
  const Mesh* m = mesh_starting_at(loaded.scene, Vec3(0, 0, 0));
  ASSERT_NE(m, nullptr);
  ASSERT_EQ(m->faces.size(), 6u) << "a triangle, a square (2) and a pentagon (3)";
  // Each corner names normal 0 at offset 1 and texture coordinate 1 at offset
  // 2: the +z normal is read only if the offsets are.
  ASSERT_EQ(m->normals.size(), m->positions.size());
  for (const Vec3& n : m->normals) EXPECT_VEC_NEAR(n, Vec3(0, 0, 1), 0.0);
  // Every triangle of a correct split faces +z, and they cover the polygons
  // exactly: 0.5 + 1 + 8 (the pentagon's area by the shoelace formula). A
  // fan of the concave pentagon has a triangle facing -z.
  double area = 0.0;
  for (const auto& f : m->faces) {
    Vec3 n = glm::cross(m->positions[f[1]] - m->positions[f[0]], m->positions[f[2]] - m->positions[f[0]]);
    EXPECT_GT(n.z, 0.0) << "triangle " << m->positions[f[0]] << " " << m->positions[f[1]] << " " << m->positions[f[2]];
    area += 0.5 * glm::length(n);
  }
  EXPECT_NEAR(area, 9.5, 1e-12);
}

TEST(ColladaMeshes, MissingNormalsAreAreaWeighted) {
  LoadedScene loaded = load_data("meshes.dae");
  // Two triangles folded along the y axis: area 2 facing +z, area 1 facing +x.
  const Mesh* m = mesh_named(loaded.scene, "folded");
  ASSERT_NE(m, nullptr);
  ASSERT_EQ(m->normals.size(), m->positions.size());
  const Vec3 shared = glm::normalize(Vec3(1, 0, 2));  // 2 * (0, 0, 1) + 1 * (1, 0, 0)
  for (size_t i = 0; i < m->positions.size(); ++i) {
    const Vec3& p = m->positions[i];
    Vec3 expected = p.x == 0.0 && p.z == 0.0 ? shared : p.x > 0.0 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
    EXPECT_VEC_NEAR(m->normals[i], expected, 1e-12) << "at " << p;
  }
}

TEST(ColladaMeshes, PolygonsStripsFansAndVertexNormals) {
  LoadedScene loaded = load_data("meshes.dae");
  const Scene& s = loaded.scene;
  auto faces_of = [&](const std::string& name) {
    size_t n = 0;
    for (const auto& m : s.meshes) n += m->name == name ? m->faces.size() : 0;
    return n;
  };
  EXPECT_EQ(faces_of("polygons"), 5u) << "a square, a triangle, and a square whose hole is ignored";
  EXPECT_EQ(count_containing(loaded.warnings, "1 hole(s)"), 1u);
  EXPECT_EQ(faces_of("strips"), 7u) << "strip 3 + fan 3 + the polylist's one triangle";
  for (const auto& m : s.meshes) {
    if (m->name != "strips") continue;
    for (const auto& f : m->faces)
      EXPECT_GT(glm::cross(m->positions[f[1]] - m->positions[f[0]], m->positions[f[2]] - m->positions[f[0]]).z, 0.0)
          << "strips alternate their corners so that every triangle keeps the winding";
  }
  EXPECT_EQ(count_containing(loaded.warnings, "1 polygon(s) with fewer than 3 corners skipped"), 1u);
  EXPECT_EQ(count_containing(loaded.warnings, "<lines>/<linestrips> element(s) ignored"), 1u);

  // Normals given through <vertices> are used (normalised), not recomputed.
  for (const auto& m : s.meshes) {
    if (m->name != "vertex-normals") continue;
    ASSERT_EQ(m->normals.size(), 3u);
    for (const Vec3& n : m->normals) EXPECT_VEC_NEAR(n, Vec3(0, 1, 0), 0.0);
  }
  EXPECT_EQ(s.triangle_count(), 6u + 2u + 5u + 1u + 7u);
}

// ---------------------------------------------------------------- lights

TEST(ColladaLights, EveryTypeWithItsPlacementAndRadiance) {
  LoadedScene loaded = load_data("lights.dae");
  const Scene& s = loaded.scene;
  auto areas = lights_of<AreaLight>(s);
  ASSERT_EQ(areas.size(), 2u);
  const AreaLight* a = areas[0]->position.y < 6 ? areas[0] : areas[1];
  const AreaLight* b = a == areas[0] ? areas[1] : areas[0];
  EXPECT_VEC_NEAR(a->position, Vec3(0, 5, 0), 1e-12);
  EXPECT_VEC_NEAR(a->dim_x, Vec3(-2, 0, 0), 1e-12);
  EXPECT_VEC_NEAR(a->dim_y, Vec3(0, 0, -3), 1e-12);
  EXPECT_VEC_NEAR(a->direction, Vec3(0, -1, 0), 1e-12);
  EXPECT_NEAR(a->area(), 6.0, 1e-12);
  EXPECT_VEC_NEAR(a->radiance, Spectrum(1, 2, 3), 0.0) << "CGL <color>";
  EXPECT_VEC_NEAR(b->radiance, Spectrum(3, 4, 5), 0.0) << "CGL <radiance>";
  EXPECT_NEAR(b->area(), 1.0, 1e-12) << "no scale: a unit square";

  auto points = lights_of<PointLight>(s);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_VEC_NEAR(points[0]->position, Vec3(1, 2, 3), 0.0);
  EXPECT_VEC_NEAR(points[0]->intensity, Spectrum(10, 20, 30), 0.0);
  EXPECT_EQ(count_containing(loaded.warnings, "attenuation ignored"), 1u);

  auto suns = lights_of<DirectionalLight>(s);
  ASSERT_EQ(suns.size(), 2u);
  const DirectionalLight* sun = suns[0]->radiance.r < 1 ? suns[0] : suns[1];
  const DirectionalLight* overridden = sun == suns[0] ? suns[1] : suns[0];
  EXPECT_VEC_NEAR(sun->direction, Vec3(-1, 0, 0), 1e-12) << "T(-z) after a quarter turn about y";
  EXPECT_VEC_NEAR(sun->radiance, Spectrum(0.5, 0.6, 0.7), 0.0);
  EXPECT_VEC_NEAR(overridden->radiance, Spectrum(2, 2, 2), 0.0) << "the CGL technique wins over technique_common";
  EXPECT_VEC_NEAR(overridden->direction, Vec3(0, 0, -1), 1e-12);

  auto skies = lights_of<SkyLight>(s);
  ASSERT_EQ(skies.size(), 1u);
  EXPECT_VEC_NEAR(skies[0]->radiance, Spectrum(0.1, 0.2, 0.3), 0.0);
  EXPECT_VEC_NEAR(s.background(Vec3(0, 1, 0)), Spectrum(0.1, 0.2, 0.3), 1e-15) << "ambient is a uniform sky";

  EXPECT_EQ(s.lights.size(), 6u) << "the spot light is skipped";
  EXPECT_EQ(count_containing(loaded.warnings, "spot lights are not supported"), 1u)
      << "one warning although it is instanced twice";
  EXPECT_EQ(count_containing(loaded.warnings, "light[@id='spot']"), 1u);
}

// ---------------------------------------------------------------- materials

TEST(ColladaMaterials, PrecedenceAndOneWarningPerApproximatedMaterial) {
  LoadedScene loaded = load_data("materials.dae");
  const Scene& s = loaded.scene;
  auto bsdf_at = [&](double x) -> const BSDF* {
    const Mesh* m = mesh_starting_at(s, Vec3(x, 0, 0));
    EXPECT_NE(m, nullptr) << "no mesh at x = " << x;
    return m ? m->bsdf : nullptr;
  };
  auto albedo_at = [&](double x) {
    const auto* d = dynamic_cast<const DiffuseBSDF*>(bsdf_at(x));
    EXPECT_NE(d, nullptr) << "the mesh at x = " << x << " should be diffuse";
    return d ? d->reflectance : Spectrum(-1.0);
  };
  const auto* emit = dynamic_cast<const EmissionBSDF*>(bsdf_at(0));
  ASSERT_NE(emit, nullptr) << "a CGL emission wins over the phong diffuse colour";
  EXPECT_VEC_NEAR(emit->radiance, Spectrum(5, 6, 7), 0.0);
  EXPECT_VEC_NEAR(albedo_at(10), Spectrum(0.2, 0.4, 0.6), 0.0) << "phong";
  EXPECT_VEC_NEAR(albedo_at(20), Spectrum(0.3, 0.3, 0.3), 0.0) << "lambert";
  EXPECT_VEC_NEAR(albedo_at(30), Spectrum(0.7, 0.1, 0.1), 0.0) << "blinn";
  EXPECT_VEC_NEAR(albedo_at(40), Spectrum(0.9, 0.8, 0.7), 0.0) << "CGL mirror: the phong diffuse colour";
  EXPECT_EQ(bsdf_at(40), bsdf_at(50)) << "one material, one BSDF however often it is bound";
  EXPECT_VEC_NEAR(albedo_at(60), Spectrum(0.5), 0.0) << "CGL glass without a diffuse colour: grey";
  EXPECT_VEC_NEAR(albedo_at(70), Spectrum(0.5), 0.0) << "CGL refraction";
  EXPECT_VEC_NEAR(albedo_at(80), Spectrum(0.4, 0.4, 0.1), 0.0) << "CGL microfacet";
  EXPECT_VEC_NEAR(albedo_at(90), Spectrum(0.5), 0.0) << "a texture: grey";
  EXPECT_VEC_NEAR(albedo_at(100), Spectrum(0.5), 0.0) << "no material: grey 0.5";
  EXPECT_VEC_NEAR(albedo_at(110), Spectrum(0.3, 0.3, 0.3), 0.0) << "unbound symbol: the first instance_material";
  const Sphere* ball = sphere_at(s, Vec3(120, 0, 0));
  ASSERT_NE(ball, nullptr);
  EXPECT_EQ(ball->get_bsdf(), bsdf_at(0)) << "a sphere takes its instance's material";

  // One warning per approximated material, naming it and what was approximated.
  for (const char* m : {"mirror", "glass", "refraction", "microfacet"}) {
    EXPECT_EQ(count_containing(loaded.warnings, std::string("material[@id='") + m + "']"), 1u) << m;
    EXPECT_EQ(count_containing(loaded.warnings, std::string("CGL <") + m + ">"), 1u) << m;
  }
  EXPECT_EQ(count_containing(loaded.warnings, "material[@id='texture']: a diffuse <texture>"), 1u);
  for (const char* m : {"emit", "phong", "lambert", "blinn"})
    EXPECT_EQ(count_containing(loaded.warnings, std::string("material[@id='") + m + "']"), 0u) << m;
  EXPECT_EQ(count_containing(loaded.warnings, "1 material(s) have a specular"), 1u) << "blinn's specular colour";
  EXPECT_EQ(count_containing(loaded.warnings, "symbol 'surface' is not bound"), 1u);
  EXPECT_EQ(count_containing(loaded.warnings, "2 shape(s) emit light but the scene has no area light"), 1u);
}

// ---------------------------------------------------------------- cameras

class ColladaCameras : public DaeFiles {
 protected:
  // A scene with one camera `perspective` (the <perspective> element's content)
  // at a node with `transform`.
  LoadedScene with_camera(const std::string& perspective, const std::string& transform = "") {
    return load(collada_document(
        R"(<library_cameras><camera id="cam"><optics><technique_common><perspective>)" + perspective +
            R"(</perspective></technique_common></optics></camera></library_cameras>)",
        std::string(kTriNode) + R"(<node id="cam-node">)" + transform + R"(<instance_camera url="#cam"/></node>)"));
  }
};

TEST_F(ColladaCameras, FieldsOfViewFromXfovYfovAndAspect) {
  Camera both = with_camera("<xfov>60</xfov><yfov>40</yfov>").scene.camera;
  EXPECT_DOUBLE_EQ(both.hfov, 60.0);
  EXPECT_DOUBLE_EQ(both.vfov, 40.0);
  Camera from_y = with_camera("<yfov>40</yfov><aspect_ratio>2</aspect_ratio>").scene.camera;
  EXPECT_NEAR(from_y.hfov, fov_of(2.0 * half_tan(40.0)), 1e-12);
  EXPECT_DOUBLE_EQ(from_y.vfov, 40.0);
  Camera x_only = with_camera("<xfov>60</xfov>").scene.camera;
  EXPECT_NEAR(x_only.vfov, fov_of(half_tan(60.0) * 3.0 / 4.0), 1e-12) << "the default image's 4:3";
  Camera clips = with_camera("<yfov>40</yfov><znear>0.25</znear><zfar>50</zfar>").scene.camera;
  EXPECT_DOUBLE_EQ(clips.near_clip, 0.25);
  EXPECT_DOUBLE_EQ(clips.far_clip, 50.0);
}

TEST_F(ColladaCameras, PlacedByLookatAndTheFirstOfSeveralIsUsed) {
  Camera c = with_camera("<yfov>40</yfov>", "<lookat>3 0 0  0 0 0  0 1 0</lookat>").scene.camera;
  EXPECT_VEC_NEAR(c.pos, Vec3(3, 0, 0), 1e-12);
  EXPECT_VEC_NEAR(-c.c2w[2], Vec3(-1, 0, 0), 1e-12);
  EXPECT_VEC_NEAR(c.c2w[1], Vec3(0, 1, 0), 1e-12);

  LoadedScene two = load(collada_document(
      R"(<library_cameras>
           <camera id="wide"><optics><technique_common><perspective><yfov>70</yfov></perspective></technique_common></optics></camera>
           <camera id="narrow"><optics><technique_common><perspective><yfov>20</yfov></perspective></technique_common></optics></camera>
         </library_cameras>)",
      std::string(kTriNode) + R"(<node id="a"><translate>0 0 5</translate><instance_camera url="#narrow"/></node>
                                 <node id="b"><instance_camera url="#wide"/></node>)"));
  EXPECT_DOUBLE_EQ(two.scene.camera.vfov, 20.0) << "the first camera in document order";
  EXPECT_VEC_NEAR(two.scene.camera.pos, Vec3(0, 0, 5), 0.0);
  EXPECT_EQ(count_containing(two.warnings, "2 cameras: the first one is used"), 1u);
}

TEST_F(ColladaCameras, OrthographicOrMissingCamerasFallBackToTheCourseFraming) {
  LoadedScene ortho = load(collada_document(
      R"(<library_cameras><camera id="o"><optics><technique_common><orthographic><xmag>1</xmag><ymag>1</ymag></orthographic></technique_common></optics></camera></library_cameras>)",
      std::string(kTriNode) + R"(<node id="o-node"><instance_camera url="#o"/></node>)"));
  EXPECT_EQ(count_containing(ortho.warnings, "only perspective cameras are supported"), 1u);
  EXPECT_EQ(count_containing(ortho.warnings, "no camera"), 1u);
  // The triangle's box is centred at (0.5, 0.5, 0) with diagonal sqrt(2): the
  // default looks along -z from 1.5 sqrt(2) away.
  EXPECT_VEC_NEAR(ortho.scene.camera.pos, Vec3(0.5, 0.5, 1.5 * std::sqrt(2.0)), 1e-12);
  EXPECT_VEC_NEAR(-ortho.scene.camera.c2w[2], Vec3(0, 0, -1), 1e-12);
}

// The course's CBgems.dae has a camera <matrix> of 15 numbers, and the course's
// reader takes it (a stream read leaves the missing number 0): so does this one.
TEST_F(ColladaCameras, AShortMatrixReadsItsMissingNumbersAsZeroWithAWarning) {
  // The last number missing: the last row is 0 0 0 0, which drops a point's w
  // as the course's renderer does; the camera sits at the matrix's (0, 1, 4).
  LoadedScene fifteen = with_camera("<yfov>40</yfov>", "<matrix>1 0 0 0  0 1 0 1  0 0 1 4  0 0 0</matrix>");
  EXPECT_VEC_NEAR(fifteen.scene.camera.pos, Vec3(0, 1, 4), 0.0);
  EXPECT_VEC_NEAR(-fifteen.scene.camera.c2w[2], Vec3(0, 0, -1), 0.0);
  EXPECT_DOUBLE_EQ(fifteen.scene.camera.vfov, 40.0);
  EXPECT_EQ(count_containing(fifteen.warnings, "node[@id='cam-node']/matrix: expected 16 numbers, got 15: the "
                                               "missing ones are read as 0, as the course's reader does"),
            1u);
  EXPECT_EQ(fifteen.warnings.size(), 1u);

  // Four numbers leave no view direction: the course viewer's default framing
  // (along -z at the box's centre from 1.5x its diagonal), the file's fovs kept.
  LoadedScene four = with_camera("<yfov>40</yfov>", "<matrix>1 0 0 2</matrix>");
  EXPECT_EQ(count_containing(four.warnings, "got 4: the missing ones are read as 0"), 1u);
  EXPECT_EQ(count_containing(four.warnings, "node[@id='cam-node']/instance_camera: a short <matrix> leaves the camera"),
            1u);
  EXPECT_VEC_NEAR(four.scene.camera.pos, Vec3(0.5, 0.5, 1.5 * std::sqrt(2.0)), 1e-12);
  EXPECT_VEC_NEAR(-four.scene.camera.c2w[2], Vec3(0, 0, -1), 1e-12);
}

using ColladaShortMatrix = DaeFiles;

TEST_F(ColladaShortMatrix, AShortMatrixOnGeometryPlacesItAsTheCoursesReaderWould) {
  // 15 numbers on a mesh node: the translation (1, 2, 3) still applies.
  LoadedScene loaded = load(collada_document(
      "", R"(<node id="n"><matrix>1 0 0 1  0 1 0 2  0 0 1 3  0 0 0</matrix><instance_geometry url="#tri"/></node>)"));
  EXPECT_TRUE(has_triangle(loaded.scene, Vec3(1, 2, 3), Vec3(2, 2, 3), Vec3(1, 3, 3)));
  EXPECT_EQ(count_containing(loaded.warnings, "node[@id='n']/matrix: expected 16 numbers, got 15"), 1u);
}

// ---------------------------------------------------------------- --course-camera

TEST(CourseCamera, CornellReframingAt480x360GivesTheCoursesVerticalFov) {
  LoadedScene loaded = load_scene((std::filesystem::path(PT_SOURCE_DIR) / "scenes/collada/cornell_spheres.dae").string(),
                                  BuildBvh::No);
  const Camera file = loaded.scene.camera;
  Camera c = course_camera(file, loaded.scene.bounds(), 480, 360);
  // The box [-1, 1] x [0, 2] x [-1, 1]: centre (0, 1, 0), diagonal sqrt(12);
  // the file camera looks along -z.
  EXPECT_VEC_NEAR(c.pos, Vec3(0, 1, 1.5 * std::sqrt(12.0)), 1e-12);
  EXPECT_VEC_NEAR(-c.c2w[2], Vec3(0, 0, -1), 1e-12);
  EXPECT_VEC_NEAR(c.c2w[1], Vec3(0, 1, 0), 1e-12);
  // The course's viewer: xfov 49.134 at 16:9 is fitted to 800 x 600 (vfov from
  // xfov at 4:3), then 480 x 360 keeps the screen distance: vfov ~ 23.25.
  double fitted_half_tan = half_tan(49.13434) / (4.0 / 3.0);
  double d = 600.0 / (2.0 * fitted_half_tan);
  EXPECT_NEAR(c.vfov, fov_of(360.0 / (2.0 * d)), 1e-9);
  EXPECT_NEAR(c.vfov, 23.25, 0.005) << "the value measured in the course's renderer";
  EXPECT_NEAR(c.hfov, fov_of(480.0 / (2.0 * d)), 1e-9);
  EXPECT_DOUBLE_EQ(c.near_clip, file.near_clip);
  EXPECT_DOUBLE_EQ(c.far_clip, file.far_clip);
}

TEST(CourseCamera, NarrowFileCamerasKeepTheirVerticalFovAndJsonScenesReframeToo) {
  // Aspect 1 (narrower than 4:3): the window keeps vfov 40, so 600 rows still
  // span 40 degrees and 300 rows span 2 atan(tan(20) / 2).
  Camera square(Vec3(0, 0, 5), Vec3(0, 0, 0), Vec3(0, 1, 0), 40.0, 40.0);
  BBox unit(Vec3(-1.0), Vec3(1.0));
  EXPECT_NEAR(course_camera(square, unit, 800, 600).vfov, 40.0, 1e-12);
  EXPECT_NEAR(course_camera(square, unit, 400, 300).vfov, fov_of(half_tan(40.0) / 2.0), 1e-12);
  // Looking straight down, the world's up cannot be used: the camera's is.
  Camera down(Vec3(0, 5, 0), Vec3(0, 0, 0), Vec3(0, 0, -1), 40.0, 40.0);
  Camera c = course_camera(down, unit, 400, 300);
  EXPECT_VEC_NEAR(c.pos, Vec3(0, 1.5 * std::sqrt(12.0), 0), 1e-12);
  EXPECT_VEC_NEAR(c.c2w[1], Vec3(0, 0, -1), 1e-12);

  LoadedScene json = load_scene((std::filesystem::path(PT_SOURCE_DIR) / "scenes/cornell_spheres.json").string(),
                                BuildBvh::No);
  Camera j = course_camera(json.scene.camera, json.scene.bounds(), 480, 360);
  EXPECT_VEC_NEAR(j.pos, Vec3(0, 0.5, 1.5 * std::sqrt(3.0)), 1e-9) << "the 1-unit box from 1.5 sqrt(3)";
}

// ---------------------------------------------------------------- library scenes

TEST(ColladaLibraryScenes, CornellSpheresInTheCoursesDialect) {
  LoadedScene loaded = load_scene((std::filesystem::path(PT_SOURCE_DIR) / "scenes/collada/cornell_spheres.dae").string());
  const Scene& s = loaded.scene;
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
  EXPECT_EQ(s.triangle_count(), 12u) << "five walls and the lamp's quad";
  EXPECT_EQ(spheres_of(s).size(), 2u);
  ASSERT_EQ(lights_of<AreaLight>(s).size(), 1u);
  EXPECT_EQ(s.lights.size(), 1u);
  const AreaLight* lamp = lights_of<AreaLight>(s)[0];
  EXPECT_VEC_NEAR(lamp->direction, Vec3(0, -1, 0), 1e-12);
  EXPECT_NEAR(lamp->area(), 0.24, 1e-12);
  BBox b = s.bounds();
  EXPECT_VEC_NEAR(b.min, Vec3(-1, 0, -1), 1e-12);
  EXPECT_VEC_NEAR(b.max, Vec3(1, 2, 1), 1e-12);
  // Every wall faces into the box.
  for (const auto& m : s.meshes)
    for (size_t i = 0; i < m->positions.size(); ++i)
      EXPECT_GT(glm::dot(m->normals[i], Vec3(0, 1, 0) - m->positions[i]), 0.0) << m->name << " at " << m->positions[i];
  ASSERT_NE(s.bvh, nullptr);
}

TEST(ColladaLibraryScenes, CourtyardUnderPointDirectionalAndAmbientLight) {
  LoadedScene loaded = load_scene((std::filesystem::path(PT_SOURCE_DIR) / "scenes/collada/courtyard.dae").string());
  const Scene& s = loaded.scene;
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
  EXPECT_EQ(lights_of<PointLight>(s).size(), 1u);
  EXPECT_EQ(lights_of<DirectionalLight>(s).size(), 1u);
  EXPECT_EQ(lights_of<SkyLight>(s).size(), 1u);
  // The floor (2), three pillars from one library node (2 hexagons of 4 + 6
  // quads of 2: 20 each), the L block (2 hexagons of 4 + 6 quads of 2) and an
  // 80-face ball.
  EXPECT_EQ(s.triangle_count(), 2u + 3u * 20u + 20u + 80u);
  EXPECT_VEC_NEAR(s.camera.pos, Vec3(6, 4.5, 8), 1e-12);
  EXPECT_VEC_NEAR(-s.camera.c2w[2], glm::normalize(Vec3(-6, -3.7, -8)), 1e-3) << "rotate lists aim it at the block";
  EXPECT_VEC_NEAR(lights_of<DirectionalLight>(s)[0]->direction, glm::normalize(Vec3(3, -6, -4)), 1e-12)
      << "<lookat> from (-3, 6, 4) to the origin";
}

// ---------------------------------------------------------------- --scene-info

TEST(SceneInfo, SummarisesADaeScene) {
  auto j = nlohmann::json::parse(scene_info_json(load_data("zup.dae")));
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"bounds", "camera", "emissive_shapes", "lights", "meshes", "spheres",
                                            "triangles", "warnings"}));
  EXPECT_EQ(j["triangles"], 3);
  EXPECT_EQ(j["spheres"], 2);
  EXPECT_EQ(j["meshes"], 2);
  EXPECT_EQ(j["lights"], nlohmann::json({{"area", 1}, {"point", 0}, {"directional", 0}, {"sky", 0}}));
  EXPECT_EQ(j["emissive_shapes"], 1);
  EXPECT_EQ(j["camera"]["position"], nlohmann::json({0.0, 1.0, 4.9}));
  EXPECT_NEAR(j["camera"]["direction"][2].get<double>(), -1.0, 1e-12);
  EXPECT_NEAR(j["camera"]["hfov"].get<double>(), 49.13434, 1e-9);
  // The boxes of the spheres (radii 1 at (-1, 3, 2), 1.5 at (-5, 0, 0)) and
  // the lamp's quad at y = 4.01 bound the scene.
  EXPECT_EQ(j["bounds"]["min"], nlohmann::json({-6.5, -1.5, -1.5}));
  EXPECT_EQ(j["bounds"]["max"], nlohmann::json({0.3, 4.01, 3.0}));
  ASSERT_EQ(j["warnings"].size(), 1u);
}

TEST(SceneInfo, SummarisesAJsonScene) {
  LoadedScene loaded = load_scene((std::filesystem::path(PT_SOURCE_DIR) / "scenes/cornell_spheres.json").string(),
                                  BuildBvh::No);
  auto j = nlohmann::json::parse(scene_info_json(loaded));
  EXPECT_EQ(j["triangles"], 12);
  EXPECT_EQ(j["spheres"], 2);
  EXPECT_EQ(j["lights"]["area"], 1);
  EXPECT_EQ(j["emissive_shapes"], 1) << "the area light's own quad";
  EXPECT_EQ(j["camera"]["vfov"], 32.0);
  EXPECT_TRUE(j["warnings"].empty());
}

}  // namespace
}  // namespace pt
