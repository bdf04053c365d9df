// Fuzz target: the COLLADA scene importer.
#include "fuzz_input.h"
#include "io/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pt::fuzz::load_as_file(data, size, "scene.dae", [](const std::string& path) { pt::load_scene(path); });
}
