#include "fuzz_input.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/scene_loader.h"

namespace fs = std::filesystem;

namespace pt::fuzz {

namespace {

void write_file(const fs::path& path, const void* data, size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || std::fwrite(data, 1, size, f) != size || std::fclose(f) != 0)
    throw std::runtime_error("fuzz harness: cannot write " + path.string());  // not a finding: abort loudly
}

// Made once and never destroyed (the exit handler still needs it).
const fs::path& private_dir() {
  static const fs::path* dir = [] {
    std::string templ = (fs::temp_directory_path() / "pt-fuzz-XXXXXX").string();
    if (!mkdtemp(templ.data())) throw std::runtime_error("fuzz harness: cannot create " + templ);
    const char mesh[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    write_file(fs::path(templ) / "mesh.obj", mesh, sizeof mesh - 1);
    std::atexit([] { fs::remove_all(private_dir()); });
    return new fs::path(templ);
  }();
  return *dir;
}

bool refused = false;

}  // namespace

int load_as_file(const uint8_t* data, size_t size, const char* file_name, void (*load)(const std::string& path)) {
  const fs::path path = private_dir() / file_name;
  write_file(path, data, size);
  refused = false;
  try {
    load(path.string());
  } catch (const SceneError&) {
    refused = true;  // the clean way to refuse an input
  }
  return 0;
}

bool last_input_refused() { return refused; }

}  // namespace pt::fuzz
