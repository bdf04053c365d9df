#pragma once
// The viewer's flip against the scene library (scenes/README.md, "The scene
// library"): the stored reference image of the scene being viewed, and the
// error model (render/relmse_model.h) from the reference's sidecar: the relMSE
// a correct render at n spp has, and how far it may lie.
#include <optional>
#include <string>

#include "render/image.h"
#include "render/relmse_model.h"
#include "render/settings.h"

namespace pt {

struct LibraryReference {
  std::string name;         // the library's name of the scene
  RenderSettings settings;  // the reference's resolution, depth, light samples, rr
  Image image;              // linear, row 0 at the top
  error_model::RelMSEModel model;
};

// The library test's z for one scene's relMSE check (scenes/README.md: alpha
// 1e-5 shared by its checks, Sidak); tests/library checks that it agrees.
constexpr double kLibraryCheckZ = 5.08;

// The library entry whose file is `scene_path`, with its image read, when
// library.json beside the scene lists it; nullopt otherwise. Throws
// std::runtime_error when the entry is there but its files cannot be read.
std::optional<LibraryReference> find_library_reference(const std::string& scene_path);

}  // namespace pt
