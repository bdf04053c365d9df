// COLLADA import of broken and hostile files: each is refused with the file
// and the place (line:column for XML syntax, an element path for content),
// and no file can crash the loader or make it run away with memory or time.
#include <gtest/gtest.h>

#include "collada_test_files.h"

namespace pt {
namespace {

using ColladaErrors = DaeFiles;

// A geometry "g" with three positions and one <triangles> whose <p> is `p`.
std::string triangles_with(const std::string& p, const std::string& count = "1") {
  return geometry(R"(<source id="g-pos"><float_array id="g-arr" count="9">0 0 0  1 0 0  0 1 0</float_array>
      <technique_common><accessor source="#g-arr" count="3" stride="3"/></technique_common></source>
    <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
    <triangles count=")" + count + R"("><input semantic="VERTEX" source="#g-v" offset="0"/><p>)" + p +
                  "</p></triangles>");
}

// A geometry "g" whose positions array holds `numbers`.
std::string positions(const std::string& numbers, const std::string& count = "9") {
  return geometry(R"(<source id="g-pos"><float_array id="g-arr" count=")" + count + R"(">)" + numbers +
                  R"(</float_array></source>
    <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#g-v" offset="0"/><p>0 1 2</p></triangles>)");
}

const std::string kG = "/COLLADA/library_geometries[2]/geometry[@id='g']";

// ---------------------------------------------------------------- XML syntax

TEST_F(ColladaErrors, XmlSyntaxErrorsGiveLineAndColumn) {
  EXPECT_TRUE(contains(error_of("<COLLADA>\n  <asset>\n</COLLADA>\n"), ":3:3: XML syntax error: Start-end tags mismatch"));
  EXPECT_TRUE(contains(error_of(""), ":1:1: XML syntax error: No document element found"));
  EXPECT_TRUE(contains(error_of("<COLLADA>\n  <asset up=\"1>\n</COLLADA>\n"), ":2:"));
  EXPECT_TRUE(contains(error_of("<?xml version=\"1.0\"?>\n<COLLADA>\n\n  <<asset/>\n</COLLADA>"), ":4:"));
  EXPECT_TRUE(contains(error_of("<scene/>"), ": /scene: not a COLLADA document"));
}

TEST_F(ColladaErrors, FilesThatCannotBeOpened) {
  LoadedScene out;
  std::string missing = (dir_ / "missing.dae").string();
  try {
    load_collada(missing, &out);
    ADD_FAILURE() << "loaded a missing file";
  } catch (const SceneError& e) {
    EXPECT_TRUE(contains(e.what(), missing + ": cannot open"));
  }
}

// ---------------------------------------------------------------- numbers

TEST_F(ColladaErrors, MalformedAndNonFiniteNumbers) {
  std::string at = ": " + kG + "/mesh/source[@id='g-pos']/float_array[@id='g-arr']: value 3 (\"";
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 nan 1 0 0 0 1 0"), kGNode)),
                       at + "nan\") is not a finite number"));
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 -inf 1 0 0 0 1 0"), kGNode)), at + "-inf\") is not a finite"));
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 1e999 1 0 0 0 1 0"), kGNode)), at + "1e999\") is not a finite"));
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 1e31 1 0 0 0 1 0"), kGNode)), at + "1e31\") is not a finite"));
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 abc 1 0 0 0 1 0"), kGNode)), at + "abc\") is not a number"));
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 0x10 1 0 0 0 1 0"), kGNode)), at + "0x10\") is not a number"));
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 1,5 1 0 0 0 1 0"), kGNode)), at + "1,5\") is not a number"));
  // Elements inside a number list are not numbers either.
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 0 <b/> 1 0 0 0 1 0"), kGNode)),
                       "float_array[@id='g-arr']/b: unexpected element inside <float_array>"));
  // '+' signs are XML Schema numbers, and text split by CDATA is one list.
  EXPECT_NO_THROW(load(collada_document(positions("+0 0 0 1 <![CDATA[0 0 0]]> 1 0"), kGNode)));
}

TEST_F(ColladaErrors, IndicesOutOfRangeOrMalformed) {
  EXPECT_TRUE(contains(error_of(collada_document(triangles_with("0 1 5"), kGNode)),
                       ": " + kG + "/mesh/triangles: index 5 at offset 0 is out of range: the positions source has 3 elements"));
  EXPECT_TRUE(contains(error_of(collada_document(triangles_with("0 1 -1"), kGNode)),
                       "/mesh/triangles/p: value 3 (\"-1\") is not a non-negative integer"));
  EXPECT_TRUE(contains(error_of(collada_document(triangles_with("0 1 4294967296"), kGNode)),
                       "value 3 (\"4294967296\") is not at most 4294967295"));
  EXPECT_TRUE(contains(error_of(collada_document(triangles_with("0 1 2.5"), kGNode)), "is not a non-negative integer"));
}

// ---------------------------------------------------------------- counts

TEST_F(ColladaErrors, CountsThatDisagreeWithTheData) {
  // The issue's example: a polylist whose <p> is short of what vcount asks.
  std::string polylist = geometry(R"(<source id="g-pos"><float_array id="g-arr" count="9">0 0 0 1 0 0 0 1 0</float_array></source>
    <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
    <polylist count="3"><input semantic="VERTEX" source="#g-v" offset="0"/><vcount>3 3 3</vcount><p>0 1 2 0 1 2 0</p></polylist>)");
  EXPECT_EQ(error_of(collada_document(polylist, kGNode)), ": " + kG + "/mesh/polylist: <p> has 7 indices, vcount needs 9");
  EXPECT_TRUE(contains(error_of(collada_document(triangles_with("0 1 2", "2"), kGNode)),
                       "/mesh/triangles: <p> has 3 indices, count=\"2\" triangles need 6"));
  // Absurd counts are compared with the data, never allocated.
  EXPECT_TRUE(contains(error_of(collada_document(triangles_with("0 1 2", "4000000000"), kGNode)),
                       "count=\"4000000000\" triangles need 12000000000"));
  EXPECT_TRUE(contains(error_of(collada_document(positions("0 0 0 1 0 0 0 1 0", "4000000000"), kGNode)),
                       "float_array[@id='g-arr']: count=\"4000000000\" but it holds 9 numbers"));
  EXPECT_TRUE(contains(error_of(collada_document(triangles_with("0 1 2", "99999999999999999999"), kGNode)),
                       "count=\"99999999999999999999\": expected an integer in [0, 4294967295]"));
  std::string huge_vcount = geometry(R"(<source id="g-pos"><float_array id="g-arr" count="9">0 0 0 1 0 0 0 1 0</float_array></source>
    <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
    <polylist count="2"><input semantic="VERTEX" source="#g-v" offset="0"/><vcount>4294967295 4294967295</vcount><p>0 1 2</p></polylist>)");
  EXPECT_TRUE(contains(error_of(collada_document(huge_vcount, kGNode)), "<p> has 3 indices, vcount needs 8589934590"));
  std::string accessor = geometry(R"(<source id="g-pos"><float_array id="g-arr" count="9">0 0 0 1 0 0 0 1 0</float_array>
      <technique_common><accessor source="#g-arr" count="4000000000" stride="3"/></technique_common></source>
    <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#g-v" offset="0"/><p>0 1 2</p></triangles>)");
  EXPECT_TRUE(contains(error_of(collada_document(accessor, kGNode)),
                       "accessor: count=\"4000000000\" with stride 3 and offset 0 needs 12000000000 numbers, the array holds 9"));
  std::string offset = geometry(R"(<source id="g-pos"><float_array id="g-arr" count="9">0 0 0 1 0 0 0 1 0</float_array></source>
    <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#g-v" offset="4000000000"/><p>0 1 2</p></triangles>)");
  EXPECT_TRUE(contains(error_of(collada_document(offset, kGNode)), "input: offset 4000000000 is too large (at most 63)"));
}

// ---------------------------------------------------------------- references

TEST_F(ColladaErrors, MissingWrongOrExternalReferences) {
  std::string missing_source = geometry(R"(<vertices id="g-v"><input semantic="POSITION" source="#nope"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#g-v" offset="0"/><p>0 1 2</p></triangles>)");
  EXPECT_TRUE(contains(error_of(collada_document(missing_source, kGNode)),
                       ": " + kG + "/mesh/vertices[@id='g-v']/input: source=\"#nope\": the file has no element with this id"));
  EXPECT_TRUE(contains(error_of(collada_document("", R"(<node id="n"><instance_geometry url="#tri-positions"/></node>)")),
                       "node[@id='n']/instance_geometry: url=\"#tri-positions\" refers to a <source>, expected a <geometry>"));
  EXPECT_TRUE(contains(error_of(collada_document("", R"(<node id="n"><instance_geometry url="other.dae#tri"/></node>)")),
                       "only references within the file (\"#id\") are supported"));
  EXPECT_TRUE(contains(error_of(collada_document("", R"(<node id="n"><instance_geometry/></node>)")),
                       "missing attribute url (a reference to a <geometry>)"));
  EXPECT_TRUE(contains(error_of(collada_document("", std::string(kTriNode) + R"(<node id="tri-node"/>)")),
                       ": /COLLADA/library_visual_scenes/visual_scene/node[2]: duplicate id 'tri-node' (also on "
                       "/COLLADA/library_visual_scenes/visual_scene/node[1])"));
  std::string no_vertex = geometry(R"(<source id="g-pos"><float_array id="g-arr">0 0 0 1 0 0 0 1 0</float_array></source>
    <triangles count="1"><input semantic="NORMAL" source="#g-pos" offset="0"/><p>0 1 2</p></triangles>)");
  EXPECT_TRUE(contains(error_of(collada_document(no_vertex, kGNode)), "/mesh/triangles: has no VERTEX input"));
  std::string no_array = geometry(R"(<source id="g-pos"><Name_array id="g-arr">a b c</Name_array></source>
    <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#g-v" offset="0"/><p>0 1 2</p></triangles>)");
  EXPECT_TRUE(contains(error_of(collada_document(no_array, kGNode)), "source[@id='g-pos']: has no <float_array>"));
}

// ---------------------------------------------------------------- the scene graph

TEST_F(ColladaErrors, InstanceNodeCyclesAndDepth) {
  std::string cycle = R"(<library_nodes>
      <node id="a"><instance_node url="#b"/></node>
      <node id="b"><instance_geometry url="#tri"/><instance_node url="#a"/></node>
    </library_nodes>)";
  EXPECT_TRUE(contains(error_of(collada_document(cycle, R"(<node id="top"><instance_node url="#a"/></node>)")),
                       "node[@id='b']/instance_node: <instance_node> makes a cycle: 'a' -> 'b' -> 'a'"));
  EXPECT_TRUE(contains(error_of(collada_document("", R"(<node id="self"><instance_node url="#self"/></node>)")),
                       "makes a cycle: 'self' -> 'self'"));

  std::string deep;
  for (int i = 0; i < 200; ++i) deep += "<node>";
  deep += R"(<instance_geometry url="#tri"/>)";
  for (int i = 0; i < 200; ++i) deep += "</node>";
  EXPECT_TRUE(contains(error_of(collada_document("", deep)), "nodes nested more than 128 deep"));
}

TEST_F(ColladaErrors, ExponentialInstancingStopsAtTheBudget) {
  // Node k instances node k+1 twice: 2^40 instances of the triangle from a
  // 3 kB file. The loader gives up at the node and triangle budgets.
  std::string nodes = "<library_nodes>";
  for (int k = 0; k < 40; ++k)
    nodes += "<node id=\"n" + std::to_string(k) + "\"><instance_node url=\"#n" + std::to_string(k + 1) +
             "\"/><instance_node url=\"#n" + std::to_string(k + 1) + "\"/></node>";
  nodes += R"(<node id="n40"><instance_geometry url="#tri"/></node></library_nodes>)";
  std::string doc = collada_document(nodes, R"(<node id="top"><instance_node url="#n0"/></node>)");
  EXPECT_TRUE(contains(error_of(doc), "more than 1000000 node instances"));
  ColladaLimits few_triangles;
  few_triangles.max_triangles = 1000;
  EXPECT_TRUE(contains(error_of(doc, few_triangles), "the scene has more than 1000 triangles after instancing"));
}

TEST_F(ColladaErrors, DeeplyNestedXmlOutsideTheSceneGraphIsHarmless) {
  // pugixml parses without recursion and the loader walks ids without it.
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "<x>";
  for (int i = 0; i < 100000; ++i) deep += "</x>";
  LoadedScene loaded = load(collada_document("<library_extra>" + deep + "</library_extra>", kTriNode));
  EXPECT_EQ(loaded.scene.triangle_count(), 1u);
}

TEST_F(ColladaErrors, TransformsThatPlaceNothing) {
  auto with_node = [&](const std::string& transform) {
    return error_of(collada_document("", R"(<node id="n">)" + transform + R"(<instance_geometry url="#tri"/></node>)"));
  };
  EXPECT_TRUE(contains(with_node("<matrix>1 0 0 0  0 1 0 0  0 0 1 0  1 2 3 1</matrix>"),
                       "node[@id='n']/matrix: the last row must be 0 0 0 1"));
  EXPECT_TRUE(contains(with_node("<matrix>1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1  0</matrix>"), "expected 16 numbers, got 17"));
  EXPECT_TRUE(contains(with_node("<rotate>0 0 0 90</rotate>"), "/rotate: the rotation axis must not be zero"));
  EXPECT_TRUE(contains(with_node("<lookat>0 0 0  0 0 0  0 1 0</lookat>"), "/lookat: eye and interest must differ"));
  EXPECT_TRUE(contains(with_node("<scale>1e20 1 1</scale><scale>1e20 1 1</scale>"),
                       "node[@id='n']/instance_geometry: the node transforms put a vertex at (1e+40, 0, 0), beyond 1e30"));
  EXPECT_TRUE(contains(error_of(collada_document("", kTriNode, "W_UP")), "/COLLADA/asset/up_axis: expected X_UP, Y_UP or Z_UP"));
}

// ---------------------------------------------------------------- lights, spheres, cameras, materials

TEST_F(ColladaErrors, LightsSpheresCamerasAndMaterialsWithImpossibleValues) {
  auto light = [&](const std::string& technique, const std::string& transform = "") {
    return error_of(collada_document("<library_lights><light id=\"l\">" + technique + "</light></library_lights>",
                                     std::string(kTriNode) + "<node id=\"ln\">" + transform +
                                         "<instance_light url=\"#l\"/></node>"));
  };
  const std::string cgl_area = R"(<extra><technique profile="CGL"><area><color>1 1 1</color></area></technique></extra>)";
  EXPECT_TRUE(contains(light(cgl_area, "<scale>0 1 1</scale>"), "node[@id='ln']/instance_light: the area light has no area"));
  EXPECT_TRUE(contains(light(R"(<technique_common><point/></technique_common>)"), "light[@id='l']/technique_common/point: missing <color>"));
  EXPECT_TRUE(contains(light(R"(<technique_common><point><color>1 -1 1</color></point></technique_common>)"),
                       "/point/color: colour components must not be negative"));
  EXPECT_TRUE(contains(light(R"(<technique_common><point><color>1 1</color></point></technique_common>)"),
                       "expected a colour of 3 numbers (r g b) or 4 (r g b a), got 2 numbers"));
  EXPECT_TRUE(contains(light("<asset/>"), "light[@id='l']: has neither a <technique_common> nor a CGL <technique>"));

  std::string sphere = R"(<library_geometries><geometry id="s"><extra><technique profile="CGL"><sphere><radius>-1</radius>
      </sphere></technique></extra></geometry></library_geometries>)";
  EXPECT_TRUE(contains(error_of(collada_document(sphere, R"(<node><instance_geometry url="#s"/></node>)")),
                       "geometry[@id='s']/extra/technique/sphere/radius: expected a positive radius, got -1"));

  auto camera = [&](const std::string& perspective) {
    return error_of(collada_document(
        "<library_cameras><camera id=\"c\"><optics><technique_common><perspective>" + perspective +
            "</perspective></technique_common></optics></camera></library_cameras>",
        std::string(kTriNode) + R"(<node id="cn"><instance_camera url="#c"/></node>)"));
  };
  EXPECT_TRUE(contains(camera("<xfov>180</xfov>"), "/perspective/xfov: expected an angle in (0, 180) degrees, got 180"));
  EXPECT_TRUE(contains(camera("<znear>1</znear>"), "/perspective: needs an <xfov> or a <yfov>"));
  EXPECT_TRUE(contains(camera("<yfov>30</yfov><aspect_ratio>0</aspect_ratio>"), "expected a positive aspect ratio"));
  EXPECT_TRUE(contains(camera("<yfov>30</yfov><znear>2</znear><zfar>1</zfar>"), "zfar must be greater than znear"));

  std::string material = R"(<library_effects><effect id="e"><profile_COMMON><technique sid="common"><phong>
      <diffuse><color>0.5 nan 0.5 1</color></diffuse></phong></technique></profile_COMMON></effect></library_effects>
    <library_materials><material id="m"><instance_effect url="#e"/></material></library_materials>)";
  EXPECT_TRUE(contains(error_of(collada_document(material, R"(<node><instance_geometry url="#tri"><bind_material>
      <technique_common><instance_material symbol="x" target="#m"/></technique_common></bind_material></instance_geometry></node>)")),
                       "effect[@id='e']/profile_COMMON/technique/phong/diffuse/color: value 2 (\"nan\") is not a finite number"));
}

TEST_F(ColladaErrors, ScenesWithNothingToRender) {
  EXPECT_TRUE(contains(error_of(collada_document("", "")),
                       "visual_scene[@id='scene']: the visual scene has no geometry"));
  EXPECT_TRUE(contains(error_of(R"(<COLLADA version="1.4.1"><asset/></COLLADA>)"),
                       ": /COLLADA: no <scene><instance_visual_scene> and no <visual_scene>: nothing to render"));
}

// ---------------------------------------------------------------- warnings

TEST_F(ColladaErrors, ApproximationsAreWarnedAboutAndTheirNumberIsBounded) {
  // Without <scene>, the first visual scene is used, with a warning.
  LoadedScene first = load(R"(<COLLADA version="1.4.1">
      <library_geometries><geometry id="s"><extra><technique profile="CGL"><sphere><radius>1</radius></sphere></technique></extra></geometry></library_geometries>
      <library_visual_scenes><visual_scene id="v"><node><instance_geometry url="#s"/></node></visual_scene></library_visual_scenes>
    </COLLADA>)");
  EXPECT_EQ(count_containing(first.warnings, "using the first one"), 1u);

  // A mesh without faces (here: only sources) is said to render nothing.
  LoadedScene empty = load(collada_document(geometry(R"(<source id="g-pos"><float_array id="g-arr">0 0 0</float_array></source>)"),
                                            std::string(kTriNode) + kGNode));
  EXPECT_EQ(count_containing(empty.warnings, "geometry[@id='g']: has no faces"), 1u);

  // 150 skinned meshes: 150 warnings about what is ignored, of which 100 are
  // kept and the rest counted.
  std::string nodes = kTriNode;
  for (int i = 0; i < 150; ++i) nodes += R"(<node><instance_controller url="#skin"/></node>)";
  LoadedScene many = load(collada_document("", nodes));
  ASSERT_EQ(many.warnings.size(), 101u);
  EXPECT_EQ(count_containing(many.warnings, "<instance_controller>) is not supported"), 100u);
  EXPECT_EQ(many.warnings.back(), "... 51 more warnings not shown") << "50 controllers and the missing camera";
}

}  // namespace
}  // namespace pt
