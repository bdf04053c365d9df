// Fuzz target: the JSON scene loader (and, through "file" keys, the OBJ loader).
#include "fuzz_input.h"
#include "io/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pt::fuzz::load_as_file(data, size, "scene.json", [](const std::string& path) { pt::load_scene(path); });
}
