// Fuzz target: the EXR reader of pathtracer-compare (read_exr), which reads
// images a student (or a hostile submission) hands in. Its clean refusal is
// std::runtime_error naming the file; here it stands for a SceneError.
#include <stdexcept>

#include "fuzz_input.h"
#include "render/image.h"
#include "io/image_file.h"
#include "io/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pt::fuzz::load_as_file(data, size, "image.exr", [](const std::string& path) {
    try {
      pt::read_exr(path);
    } catch (const std::runtime_error& e) {
      throw pt::SceneError(e.what());
    }
  });
}
