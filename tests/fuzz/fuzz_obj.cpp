// Fuzz target: the OBJ mesh loader.
#include "fuzz_input.h"
#include "io/obj_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pt::fuzz::load_as_file(data, size, "mesh_under_test.obj", [](const std::string& path) {
    std::vector<std::string> warnings;
    pt::load_obj(path, pt::MeshTransform{}, &warnings);
  });
}
