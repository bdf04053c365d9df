#pragma once
// Helpers of the COLLADA importer's tests (test_collada.cpp, test_collada_errors.cpp):
// the stored test files, scenes written on the fly, and looking up what was loaded.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "io/collada_loader.h"
#include "pt_source_dir.h"
#include "support/assertions.h"

namespace pt {

inline const std::filesystem::path kColladaData =
    std::filesystem::path(PT_SOURCE_DIR) / "tests" / "framework" / "data" / "collada";

using test::contains;

// Warnings that contain `part`.
inline size_t count_containing(const std::vector<std::string>& warnings, const std::string& part) {
  size_t n = 0;
  for (const auto& w : warnings) n += w.find(part) != std::string::npos;
  return n;
}

// A whole COLLADA document around `libraries` (library elements) and `nodes`
// (the visual scene's nodes). It always defines geometry "tri", the triangle
// (0,0,0) (1,0,0) (0,1,0), so a scene needs only a node instancing it.
inline std::string collada_document(const std::string& libraries, const std::string& nodes,
                                    const std::string& up_axis = "Y_UP") {
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>)" + up_axis + R"(</up_axis></asset>
  <library_geometries>
    <geometry id="tri">
      <mesh>
        <source id="tri-positions">
          <float_array id="tri-positions-array" count="9">0 0 0  1 0 0  0 1 0</float_array>
          <technique_common><accessor source="#tri-positions-array" count="3" stride="3"/></technique_common>
        </source>
        <vertices id="tri-vertices"><input semantic="POSITION" source="#tri-positions"/></vertices>
        <triangles count="1">
          <input semantic="VERTEX" source="#tri-vertices" offset="0"/>
          <p>0 1 2</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
)" + libraries + R"(
  <library_visual_scenes>
    <visual_scene id="scene">
)" + nodes + R"(
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
}

inline const char* kTriNode = R"(<node id="tri-node"><instance_geometry url="#tri"/></node>)";

// A geometry "g" whose <mesh> is `mesh` (sources, vertices and primitives).
inline std::string geometry(const std::string& mesh) {
  return R"(<library_geometries><geometry id="g"><mesh>)" + mesh + R"(</mesh></geometry></library_geometries>)";
}
inline const char* kGNode = R"(<node id="g-node"><instance_geometry url="#g"/></node>)";

// Each test writes its files into a directory of its own.
class DaeFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("pt_collada_" + std::to_string(getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& text, const std::string& name = "scene.dae") {
    std::filesystem::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }

  LoadedScene load(const std::string& text, const ColladaLimits& limits = {}) {
    LoadedScene out;
    load_collada(write(text), &out, limits);
    return out;
  }

  // The message the loader throws for `text`, which must start with the file;
  // fails the test if the text loads.
  std::string error_of(const std::string& text, const ColladaLimits& limits = {}) {
    std::string path = write(text);
    try {
      LoadedScene out;
      load_collada(path, &out, limits);
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path + ":", 0), 0u) << "the message should start with the file: " << e.what();
      return std::string(e.what()).substr(path.size());
    }
    ADD_FAILURE() << "loaded without an error:\n" << text;
    return "";
  }

  std::filesystem::path dir_;
};

// The triangles of every mesh, as world-space corner triples.
inline std::vector<std::array<Vec3, 3>> triangles_of(const Scene& s) {
  std::vector<std::array<Vec3, 3>> out;
  for (const auto& m : s.meshes)
    for (const auto& f : m->faces) out.push_back({m->positions[f[0]], m->positions[f[1]], m->positions[f[2]]});
  return out;
}

// Whether the scene has the triangle a, b, c with this winding (any corner first).
inline ::testing::AssertionResult has_triangle(const Scene& s, const Vec3& a, const Vec3& b, const Vec3& c) {
  auto near = [](const Vec3& p, const Vec3& q) { return glm::length(p - q) < 1e-9; };
  for (const auto& t : triangles_of(s))
    for (int k = 0; k < 3; ++k)
      if (near(t[k], a) && near(t[(k + 1) % 3], b) && near(t[(k + 2) % 3], c)) return ::testing::AssertionSuccess();
  auto result = ::testing::AssertionFailure() << "no triangle " << a << " " << b << " " << c << "; the scene has:";
  for (const auto& t : triangles_of(s)) result << "\n  " << t[0] << " " << t[1] << " " << t[2];
  return result;
}

}  // namespace pt
