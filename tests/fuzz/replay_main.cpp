// Replays stored fuzz inputs through a fuzz target without libFuzzer, so that
// every build (any compiler) checks them:
//   fuzz-replay-obj tests/fuzz/corpus/obj --refused tests/fuzz/crashers/obj
// Arguments are files or directories of files. Inputs before --refused must
// load or be refused with a SceneError; inputs after it (crashers: each once
// broke a loader, and the fix refuses it) must be refused with a SceneError,
// so that a fix undone fails here even where the original failure was silent
// undefined behaviour. Exits 1 naming the first input that breaks its rule; a
// crash or a hang shows as the test crashing or timing out.
#include <algorithm>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> files_in(const fs::path& arg) {
  std::vector<fs::path> files;
  if (fs::is_directory(arg)) {
    for (const auto& entry : fs::directory_iterator(arg))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
  } else {
    files.push_back(arg);
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  bool must_refuse = false;
  size_t replayed = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--refused") {
      must_refuse = true;
      continue;
    }
    for (const fs::path& path : files_in(argv[i])) {
      std::ifstream in(path, std::ios::binary);
      if (!in) {
        std::cerr << path.string() << ": cannot open\n";
        return 1;
      }
      std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      try {
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      } catch (const std::exception& e) {
        std::cerr << path.string() << ": the loader let through an exception other than SceneError: " << e.what()
                  << "\n";
        return 1;
      }
      if (must_refuse && !pt::fuzz::last_input_refused()) {
        std::cerr << path.string() << ": this input once broke the loader and must be refused with a SceneError, "
                  << "but it loaded\n";
        return 1;
      }
      ++replayed;
    }
  }
  std::cout << "replayed " << replayed << " inputs, each loaded or refused as it must\n";
  return replayed == 0 ? 1 : 0;  // an empty corpus would make this test vacuous
}
