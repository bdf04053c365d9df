// pt-release-check: proves that a student release holds no solution.
//
//   pt-release-check --release DIR --source DIR --manifest FILE
//
// Fails (exit 1, listing each finding) when
//  * a file or folder of the release is one the release must leave out
//    (reference/, tests/mutants/, tests/hostile/, tests/partN/hidden/,
//    tests/support/compiled/, tools/bench/ladder.*);
//  * any file of it (text, or the bytes of a binary: the prebuilt libraries
//    included) holds a non-trivial line of SOURCE/reference/*.cpp: at least 24
//    characters once whitespace is removed (shorter lines are declarations
//    like `size_t max_leaf_size_;`), not an #include, not a line of the
//    release's own stubs or framework headers (a task's signature is in both,
//    rightly), and not an idiom: a line that two or more files of the
//    checkout outside reference/ also hold (`Intersection isect;`, a loop
//    header) says nothing of the solution. A solution line copied into one
//    shipped file is caught; the same line copied into two is taken for an
//    idiom (the price of not flagging every loop header);
//  * any file but the handouts names a hidden test (Suite.Name, or a Name of
//    10 characters or more): the handouts name and describe every hidden test
//    on purpose (issue 8), everything else must not.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "manifest.h"

namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string squeezed(const std::string& line) {
  std::string s;
  for (unsigned char c : line)
    if (!std::isspace(c)) s += static_cast<char>(c);
  return s;
}

std::string trimmed(const std::string& line) {
  const auto b = line.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return line.substr(b, line.find_last_not_of(" \t\r") - b + 1);
}

bool telling(const std::string& line) {
  const std::string t = trimmed(line);
  return squeezed(t).size() >= 24 && t.rfind("#include", 0) != 0;
}

bool is_text(const std::string& bytes) { return bytes.find('\0') == std::string::npos; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string release, source, manifest_path;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--release") release = argv[i + 1];
    else if (a == "--source") source = argv[i + 1];
    else if (a == "--manifest") manifest_path = argv[i + 1];
  }
  if (release.empty() || source.empty() || manifest_path.empty() || !fs::is_directory(release) ||
      !fs::is_directory(fs::path(source) / "reference")) {
    std::fprintf(stderr, "usage: pt-release-check --release DIR --source CHECKOUT --manifest FILE\n");
    return 2;
  }
  const fs::path reference = fs::path(source) / "reference";
  std::vector<std::string> findings;

  // Every file of the release, with its path relative to the release.
  std::vector<std::pair<std::string, fs::path>> files;
  for (const auto& e : fs::recursive_directory_iterator(release)) {
    const std::string rel = fs::relative(e.path(), release).generic_string();
    // A folder named reference/ anywhere holds the solution, except the
    // scene library's stored reference images, which the release must carry.
    static const std::vector<std::string> banned = {"/reference/", "tests/mutants", "tests/hostile", "/hidden/",
                                                    "/hidden", "tests/support/compiled", "ladder."};
    const std::string anchored = "/" + rel + (e.is_directory() ? "/" : "");
    const bool scene_images = rel.rfind("scenes/reference", 0) == 0 && !e.is_directory() &&
                              std::regex_match(rel, std::regex(R"(scenes/reference/[A-Za-z0-9_]+\.(exr|png|json))"));
    for (const auto& b : banned)
      if (anchored.find(b) != std::string::npos && !(b == "/reference/" && (scene_images || anchored == "/scenes/reference/")))
        findings.push_back(rel + ": the release must leave this out");
    if (e.is_regular_file()) files.push_back({rel, e.path()});
  }

  // The API both sides share: the release's stubs and framework.
  std::set<std::string> shared;
  for (const auto& [rel, path] : files)
    if (rel.rfind("tasks/", 0) == 0 || rel.rfind("skeleton/", 0) == 0)
      for (const auto& l : lines_of(read_file(path))) shared.insert(squeezed(l));

  // Idioms: lines two or more files of the checkout outside reference/ hold.
  std::map<std::string, int> files_holding;
  for (const char* dir : {"skeleton", "tasks", "tests", "tools"}) {
    if (!fs::is_directory(fs::path(source) / dir)) continue;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(source) / dir)) {
      const auto ext = e.path().extension();
      if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h" && ext != ".cmake")) continue;
      std::set<std::string> once;
      for (const auto& l : lines_of(read_file(e.path()))) once.insert(squeezed(l));
      for (const auto& l : once) ++files_holding[l];
    }
  }

  // The solution's telling lines.
  std::map<std::string, std::string> solution;  // squeezed -> "reference/file:line"
  std::vector<std::pair<std::string, std::string>> raw;  // trimmed text, where
  for (const auto& e : fs::directory_iterator(reference)) {
    if (e.path().extension() != ".cpp") continue;
    int n = 0;
    for (const auto& l : lines_of(read_file(e.path()))) {
      ++n;
      if (!telling(l) || shared.count(squeezed(l))) continue;
      if (auto it = files_holding.find(squeezed(l)); it != files_holding.end() && it->second >= 2) continue;
      const std::string where = "reference/" + e.path().filename().string() + ":" + std::to_string(n);
      solution.emplace(squeezed(l), where);
      raw.push_back({trimmed(l), where});
    }
  }

  // Hidden test names.
  std::vector<std::string> hidden;
  const pt::grade::Manifest manifest = pt::grade::read_manifest(manifest_path);
  for (const auto& [part, tests] : manifest.parts)
    for (const auto& t : tests)
      if (t.hidden) {
        hidden.push_back(t.name);
        const std::string bare = t.name.substr(t.name.find('.') + 1);
        if (bare.size() >= 10) hidden.push_back(bare);
      }

  size_t scanned_bytes = 0;
  for (const auto& [rel, path] : files) {
    const std::string bytes = read_file(path);
    scanned_bytes += bytes.size();
    if (is_text(bytes)) {
      int n = 0;
      for (const auto& l : lines_of(bytes)) {
        ++n;
        auto it = solution.find(squeezed(l));
        if (it != solution.end()) findings.push_back(rel + ":" + std::to_string(n) + ": a line of " + it->second);
      }
    } else {
      for (const auto& [text, where] : raw)
        if (text.size() >= 24 && bytes.find(text) != std::string::npos)
          findings.push_back(rel + ": holds the text of " + where);
    }
    if (rel.rfind("handouts/", 0) == 0) continue;
    for (const auto& h : hidden)
      if (bytes.find(h) != std::string::npos) findings.push_back(rel + ": names the hidden test " + h);
  }

  if (!findings.empty()) {
    std::printf("the release at %s is not clean (%zu findings):\n", release.c_str(), findings.size());
    for (size_t i = 0; i < findings.size() && i < 50; ++i) std::printf("  %s\n", findings[i].c_str());
    return 1;
  }
  std::printf("release clean: %zu files (%.1f MB) hold none of %zu solution lines and none of %zu hidden test names "
              "(handouts name them on purpose)\n",
              files.size(), scanned_bytes / 1e6, solution.size(), hidden.size());
  return 0;
}
