// The library's files: the manifest loads and refuses mistakes by name and
// place, every stored reference is complete and matches its manifest entry,
// and the per-pass command recorded in the sidecars renders exactly what the
// in-process renders of pt-reference-images and of the library test render.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "support/assertions.h"
#include "support/reference_image.h"
#include "support/scene_library.h"

namespace fs = std::filesystem;

namespace pt::library {
namespace {

using test::contains;

fs::path scratch(const std::string& what) {
  fs::path d = fs::temp_directory_path() / ("pt_library_" + std::to_string(getpid()) + "_" + what);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// One valid entry; tests splice mistakes into copies of it.
nlohmann::json valid_manifest() {
  return nlohmann::json::parse(R"({
    "description": "test",
    "scenes": [{"name": "box", "file": "box.json", "purpose": "a test",
                "render": {"width": 32, "height": 24, "light_samples": 1, "max_depth": 2, "rr": 0.7},
                "reference": {"samples": 64, "pass_samples": 4, "seed": 100},
                "check": {"samples": 8, "seed": 1}}]})");
}

// The message load_library throws for a manifest `text`; fails the test if it loads.
std::string error_of(const std::string& text) {
  fs::path d = scratch("manifest");
  std::ofstream(d / "library.json") << text;
  try {
    load_library((d / "library.json").string(), "/nonexistent");
  } catch (const std::exception& e) {
    return e.what();
  }
  ADD_FAILURE() << "the manifest loaded: " << text;
  return "";
}
std::string error_of(const nlohmann::json& manifest) { return error_of(manifest.dump()); }

TEST(LibraryManifest, LoadsAValidEntry) {
  fs::path d = scratch("valid");
  std::ofstream(d / "library.json") << valid_manifest().dump();
  Library lib = load_library((d / "library.json").string(), "/generated");
  ASSERT_EQ(lib.scenes.size(), 1u);
  const LibraryScene& s = lib.find("box");
  EXPECT_EQ(s.path, (d / "box.json").string());
  EXPECT_EQ(s.passes(), 16);
  EXPECT_EQ(lib.reference_dir, (d / "reference").string());
  EXPECT_THROW(lib.find("nothing"), std::out_of_range);
  RenderSettings rs = s.settings(8, 5);
  EXPECT_EQ(rs.width, 32);
  EXPECT_EQ(rs.ns_aa, 8);
  EXPECT_EQ(rs.max_ray_depth, 2);
  EXPECT_EQ(rs.seed, 5u);
}

TEST(LibraryManifest, GeneratedScenesResolveInTheBuildTree) {
  nlohmann::json m = valid_manifest();
  m["scenes"][0]["generated"] = "pt-procedural-mesh -n 3";
  fs::path d = scratch("generated");
  std::ofstream(d / "library.json") << m.dump();
  EXPECT_EQ(load_library((d / "library.json").string(), "/build/scenes").scenes[0].path, "/build/scenes/box.json");
}

TEST(LibraryManifest, RefusesMistakesNamingThePlace) {
  struct Case {
    const char* pointer;  // where to splice
    nlohmann::json value;
    const char* message;
  };
  const Case cases[] = {
      {"/scenes/0/render/widht", 32, "/scenes/0/render/widht: unknown key"},
      {"/scenes/0/render/width", -1, "/scenes/0/render/width: expected an integer"},
      {"/scenes/0/render/rr", 0.0, "/scenes/0/render/rr: expected a number"},
      {"/scenes/0/reference/samples", 66, "/scenes/0/reference/samples: expected a multiple"},
      {"/scenes/0/reference/pass_samples", 1, "/scenes/0/reference/pass_samples: expected an integer in [2"},
      {"/scenes/0/check/seed", 105, "/scenes/0/check/seed: must differ from the reference's seeds 100 to 115"},
      {"/scenes/0/name", "a b", "/scenes/0/name: expected a file stem"},
      {"/scenes/0/purpose", 3, "/scenes/0/purpose: expected a string"},
      {"/scenes", nlohmann::json::array(), "/scenes: expected a non-empty array"},
  };
  for (const Case& c : cases) {
    nlohmann::json m = valid_manifest();
    m[nlohmann::json::json_pointer(c.pointer)] = c.value;
    std::string err = error_of(m);
    EXPECT_TRUE(contains(err, "library.json: " + std::string(c.message))) << c.pointer;
  }
  nlohmann::json missing = valid_manifest();
  missing["scenes"][0].erase("check");
  EXPECT_TRUE(contains(error_of(missing), "/scenes/0/check: missing"));
  nlohmann::json twice = valid_manifest();
  twice["scenes"].push_back(twice["scenes"][0]);
  twice["scenes"][1]["check"]["seed"] = 2;
  EXPECT_TRUE(contains(error_of(twice), "/scenes/1/name: duplicate name \"box\""));
}

TEST(LibraryManifest, SyntaxErrorNamesTheFile) {
  EXPECT_TRUE(contains(error_of(std::string("{\"scenes\": [,]}")), "library.json: [json.exception.parse_error"));
}

// Every entry of the repository's manifest has its four files, of the
// manifest's size, and a sidecar that says how it was made with the settings
// the manifest gives now (a changed entry needs new images).
TEST(LibraryReferences, EveryEntryHasItsFilesAndSettings) {
  const Library lib = load_library(default_manifest(), PT_GENERATED_SCENES_DIR);
  for (const LibraryScene& s : lib.scenes) {
    SCOPED_TRACE(s.name);
    const ReferencePaths p = reference_paths(lib.reference_dir, s.name);
    for (const std::string& f : {p.mean, p.sd, p.sidecar, p.preview}) EXPECT_TRUE(fs::exists(f)) << f;
    const ReferenceImage ref = read_reference(lib.reference_dir, s.name);
    EXPECT_EQ(ref.mean.width, s.width);
    EXPECT_EQ(ref.mean.height, s.height);
    EXPECT_EQ(ref.model.reference_samples, s.reference_samples);
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(p.sidecar));
    const nlohmann::json& st = j.at("settings");
    EXPECT_EQ(st.at("samples").get<int>(), s.reference_samples);
    EXPECT_EQ(st.at("pass_samples").get<int>(), s.pass_samples);
    EXPECT_EQ(st.at("light_samples").get<int>(), s.light_samples);
    EXPECT_EQ(st.at("max_depth").get<int>(), s.max_depth);
    EXPECT_EQ(st.at("rr").get<double>(), s.rr);
    EXPECT_EQ(st.at("seed").get<uint64_t>(), s.reference_seed);
    for (const char* key : {"command", "pass_command", "render_seconds", "git", "validation"})
      EXPECT_TRUE(j.contains(key)) << key;
  }
}

TEST(LibraryReferences, MissingFileIsNamed) {
  fs::path d = scratch("missing");
  try {
    read_reference(d.string(), "nothing");
    ADD_FAILURE() << "read_reference did not throw";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(contains(e.what(), (d / "nothing.exr").string()));
  }
}

// The sidecars' pass_command is LibraryScene::command: run with the command
// line renderer, it must write exactly the in-process render (at a small size,
// so that the test takes a fraction of a second).
TEST(LibraryReferences, CommandRendersWhatTheLibraryRenders) {
  LibraryScene s = load_library(default_manifest(), PT_GENERATED_SCENES_DIR).find("cornell_spheres");
  s.width = 24, s.height = 18;
  fs::path d = scratch("command");
  const std::string png = (d / "pass.png").string();
  const std::string cmd = s.command(4, 12345, png);
  ASSERT_EQ(cmd.rfind("pathtracer-reference ", 0), 0u) << cmd;
  const std::string run = std::string(PT_PATHTRACER_REFERENCE) + cmd.substr(std::string("pathtracer-reference").size());
  ASSERT_EQ(std::system((run + " 2>/dev/null").c_str()), 0) << run;
  const Image from_cli = read_exr((d / "pass.exr").string());
  LoadedScene loaded = load(s);
  const RenderResult r = render(s, loaded.scene, 4, 12345, 2);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(from_cli.pixels.size(), r.image.pixels.size());
  for (size_t i = 0; i < r.image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(float(from_cli.pixels[i][c]), float(r.image.pixels[i][c])) << "pixel " << i << " channel " << c << ": " << cmd;
}

}  // namespace
}  // namespace pt::library
