// Hostile: the report's renderer fills the disk. Run as the renderer (the
// test binaries are left honest), it writes 64 MiB files (the sandbox's limit
// on one file) into the folder it was given for its image until a write
// fails or 2 GiB are there (so that a grader without a bound costs the CI
// machine 2 GiB, not its disk), then fails the render.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

extern "C" [[noreturn]] void _exit(int status);

namespace {
void fill_once() {
  static bool done = false;
  if (done) return;
  done = true;
  std::ifstream in("/proc/self/cmdline");
  std::vector<std::string> args;
  for (std::string a; std::getline(in, a, '\0');) args.push_back(a);
  if (args.empty() || args[0].find("pathtracer") == std::string::npos) return;
  std::string image;
  for (size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "-f") image = args[i + 1];
  const std::string dir = image.substr(0, image.rfind('/'));
  const std::vector<char> block(1 << 20, 'x');
  for (int n = 0; n < 32; ++n) {
    const std::string name = dir + "/fill-" + std::to_string(n);
    if (std::FILE* exists = std::fopen(name.c_str(), "rb")) {  // an earlier render's: the 2 GiB stay 2 GiB
      std::fclose(exists);
      continue;
    }
    std::FILE* f = std::fopen(name.c_str(), "wb");
    if (!f) break;
    bool full = false;
    for (int mib = 0; mib < 64 && !full; ++mib) full = std::fwrite(block.data(), 1, block.size(), f) != block.size();
    full = std::fclose(f) != 0 || full;
    if (full) break;
  }
  _exit(3);
}
}  // namespace
