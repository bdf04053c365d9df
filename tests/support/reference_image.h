#pragma once
// A stored reference image of the scene library, as scenes/reference/ holds it:
//   <name>.exr      the mean of `samples` samples per pixel (linear, float, ZIP)
//   <name>_sd.exr   the per-sample standard deviation of each pixel and channel
//                   (half, ZIP): an n-spp render's pixel has sd sd / sqrt(n)
//   <name>.json     the sidecar: settings, seeds, time, the commands, the git
//                   state of the solution (instructors' copies only: the
//                   student release leaves it out), the error model's constants and their
//                   validation (written by pt-reference-images)
//   <name>.png      a preview for people
#include <string>

#include "render/image.h"
#include "io/image_file.h"
#include "support/error_model.h"

namespace pt::library {

struct ReferenceImage {
  std::string name;
  Image mean;
  Image sd;
  error_model::RelMSEModel model;  // from the sidecar; model.reference_samples is N
};

struct ReferencePaths {
  std::string mean, sd, sidecar, preview;
};
ReferencePaths reference_paths(const std::string& dir, const std::string& name);

// Throws std::runtime_error naming the file when one is missing or malformed,
// or when the images' sizes differ.
ReferenceImage read_reference(const std::string& dir, const std::string& name);

// A linear EXR with half-float channels (ZIP): for the sd image, whose own
// noise is far above half precision. The mean stays float (write_exr): a
// rounding error shared by thousands of noise-free pixels would add up.
void write_half_exr(const std::string& path, const Image& image);

}  // namespace pt::library
