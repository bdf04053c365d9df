#pragma once
// The viewer's flip against the scene library (scenes/README.md, "The scene
// library"): the stored reference image of the scene being viewed, and the
// error model's expected relMSE for a correct render at n spp,
//   E[relMSE] = a (1/n + 1/N),  sd = sqrt(c2 (1/n + 1/N)^2 + c3 / n^3),
// with a, c2, c3 and N from the reference's sidecar.
#include <optional>
#include <string>

#include "render/image.h"
#include "render/settings.h"

namespace pt {

struct LibraryReference {
  std::string name;         // the library's name of the scene
  RenderSettings settings;  // the reference's resolution, depth, light samples, rr
  Image image;              // linear, row 0 at the top
  double a = 0, c2 = 0, c3 = 0, reference_samples = 1;

  double expected_relmse(double n) const { return a * (1 / n + 1 / reference_samples); }
  double sd_relmse(double n) const;
};

// The library entry whose file is `scene_path`, with its image read, when
// library.json beside the scene lists it; nullopt otherwise. Throws
// std::runtime_error when the entry is there but its files cannot be read.
std::optional<LibraryReference> find_library_reference(const std::string& scene_path);

}  // namespace pt
