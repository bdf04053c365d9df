#pragma once
// The scene library (scenes/library.json): the scenes every study, test and
// report renders, each with the settings of its stored reference image.
//
// One entry per scene:
//   {"name": "cornell_spheres", "file": "cornell_spheres.json", "purpose": "...",
//    "render": {"width": 256, "height": 192, "light_samples": 1, "max_depth": 5, "rr": 0.7},
//    "reference": {"samples": 8192, "pass_samples": 4, "seed": 1000000},
//    "check": {"samples": 16, "seed": 7}}
// "file" is relative to scenes/, or, for a scene the build writes (the
// procedural mesh), to <build>/scenes/ when the entry says
// "generated": "<tool> <arguments>" (tools/CMakeLists.txt runs that command
// with "-o <build>/scenes/<stem of file>"). Unknown keys are errors.
//
// Reference images live in scenes/reference/<name>.exr (the mean),
// <name>_sd.exr (per-sample standard deviation), <name>.json (the sidecar)
// and <name>.png (a preview); reference_image.h reads them.
#include <cstdint>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "render/settings.h"
#include "scene/scene.h"
#include "io/scene_loader.h"

namespace pt::library {

struct LibraryScene {
  std::string name;     // file stem of its reference images
  std::string file;     // as written in the manifest
  std::string path;     // resolved: where to load it from
  std::string purpose;  // one line: what it is for
  std::string generated;  // the command that writes it at build time; empty for stored scenes
  // Render settings shared by the reference and every comparison with it.
  int width = 256, height = 192, light_samples = 1, max_depth = 5;
  double rr = 0.7;
  // The reference: `samples` per pixel in passes of `pass_samples`, pass k
  // rendered with seed `seed + k` (so its per-pixel variance is measured).
  int reference_samples = 0, pass_samples = 0;
  uint64_t reference_seed = 0;
  // The library test: one render at `check_samples` with `check_seed`.
  int check_samples = 0;
  uint64_t check_seed = 0;

  int passes() const { return reference_samples / pass_samples; }
  // Settings of one render of this scene at `spp` with `seed`.
  RenderSettings settings(int spp, uint64_t seed) const;
  // The `pathtracer-reference` command line that renders exactly what
  // render() below renders (same image, bit for bit), writing `output`.
  std::string command(int spp, uint64_t seed, const std::string& output) const;
  // The same, as the arguments of any build's `pathtracer` (argv[1..]).
  std::vector<std::string> arguments(int spp, uint64_t seed, const std::string& output) const;
};

struct Library {
  std::string manifest;       // path of library.json
  std::string scenes_dir;     // its directory
  std::string reference_dir;  // scenes_dir/reference
  std::vector<LibraryScene> scenes;
  const LibraryScene& find(const std::string& name) const;  // throws std::out_of_range naming it
};

// Reads the manifest; `generated_dir` is where the build wrote the generated
// scenes (<build>/scenes). Throws std::runtime_error "library.json: /scenes/2/render/width: ..."
// on a malformed manifest.
Library load_library(const std::string& manifest, const std::string& generated_dir);
// The repository's manifest, scenes/library.json.
std::string default_manifest();

// Loads the scene (its BVH built with this binary's Part 2) and renders it at
// `spp` with `seed`, exactly as `pathtracer-reference` does with the flags of
// LibraryScene::command. Throws SceneError when the file does not load.
RenderResult render(const LibraryScene& s, const Scene& scene, int spp, uint64_t seed, int threads);
LoadedScene load(const LibraryScene& s);

}  // namespace pt::library
