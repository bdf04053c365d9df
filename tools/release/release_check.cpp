// pt-release-check: proves that a student release holds no solution.
//
//   pt-release-check --release DIR --source DIR --manifest FILE
//
// Fails (exit 1, listing each finding) when
//  * a file or folder of the release is one the release must leave out
//    (reference/, tests/mutants/, autograder/hostile/, tests/partN/hidden/,
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
//    on purpose, everything else must not;
//  * what a student reads (the documents, the framework's headers, the task
//    files, the visible tests and their support) names a path of the course's
//    folders that the release does not hold (a README left behind by a move,
//    `reference/`, DESIGN.md), with the file and line;
//  * a prebuilt library keeps a local symbol (a helper's name says how the
//    solution works: strip -x), or an image's sidecar keeps a commit hash.
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

#include "process/command.h"
#include "run/manifest.h"

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

// What a student reads: a path in it must be one the release holds.
bool read_by_students(const std::string& rel) {
  const std::string ext = fs::path(rel).extension().string();
  if (ext == ".md") return true;
  for (const char* dir : {"skeleton/", "tasks/", "tests/support/", "tests/part"})
    if (rel.rfind(dir, 0) == 0 && (ext == ".h" || ext == ".cpp")) return true;
  return false;
}

// Paths under the course's top folders that `text` names and `release` does
// not hold. Placeholders (partN, <scene>, globs) are not paths.
std::vector<std::string> missing_paths(const std::string& rel, const std::string& text, const fs::path& release) {
  static const std::regex path(
      R"((^|[^A-Za-z0-9_./-])((skeleton|tasks|tests|scenes|handouts|prebuilt|tools|autograder|docs|reference|build)/[A-Za-z0-9_./-]*))");
  static const std::regex citation(R"(([A-Za-z0-9_]+\.(cpp|h)):([0-9]+): Failure)");
  std::vector<std::string> found;
  int n = 0;
  for (const auto& line : lines_of(text)) {
    ++n;
    // A failure quoted in a document: its file:line must be an assertion.
    std::smatch m;
    if (std::regex_search(line, m, citation)) {
      const std::string cited = m[1], at = m[3];
      bool asserts = false, seen = false;
      for (const auto& e : fs::recursive_directory_iterator(release / "tests")) {
        if (e.path().filename() != cited) continue;
        seen = true;
        const auto lines = lines_of(read_file(e.path()));
        const size_t k = std::stoul(at);
        asserts = asserts || (k >= 1 && k <= lines.size() && std::regex_search(lines[k - 1], std::regex("ASSERT|EXPECT|FAIL")));
      }
      if (!seen) found.push_back(rel + ":" + std::to_string(n) + ": quotes " + cited + ", which the release does not hold");
      else if (!asserts)
        found.push_back(rel + ":" + std::to_string(n) + ": quotes " + cited + ":" + at + ", which is not an assertion");
    }
    if (line.find("DESIGN.md") != std::string::npos || line.find("DESIGN section") != std::string::npos)
      found.push_back(rel + ":" + std::to_string(n) + ": names DESIGN.md, which the release does not hold");
    for (auto it = std::sregex_iterator(line.begin(), line.end(), path); it != std::sregex_iterator(); ++it) {
      std::string p = (*it)[2];
      const size_t end = (*it).position(2) + p.size();
      while (!p.empty() && (p.back() == '.' || p.back() == '/' || p.back() == '-')) p.pop_back();
      if (p.rfind("build/", 0) == 0) continue;  // what a build writes
      if (end < line.size() && std::string("<*{$").find(line[end]) != std::string::npos) continue;
      if (std::regex_search(p, std::regex(R"(partN|N_|XXX|\.\.\.|/[a-z]\.[a-z]+$)"))) continue;  // x.json: an example
      // A path is a file with an extension or a folder written with its
      // slash ("intersection tests/ray" is neither).
      const bool folder = end < line.size() && line[end] == '/';
      if (fs::path(p).extension().empty() && !folder && (*it)[2].str().back() != '/') continue;
      if (line.find("cannot open") != std::string::npos) continue;  // an error message shown on purpose
      // Relative to the release, or to the document's own folder.
      if (!fs::exists(release / p) && !fs::exists(release / fs::path(rel).parent_path() / p))
        found.push_back(rel + ":" + std::to_string(n) + ": names " + p + ", which the release does not hold");
    }
  }
  return found;
}

// Local symbols (nm's lower-case types) other than the assembler's own
// labels (.L...), in each member of an archive.
// The archive's local symbols; "(unreadable)" when no nm here reads it (GNU
// nm reads no Mach-O: a Mac's libraries, added by add_prebuilt.cmake, need
// LLVM's).
std::vector<std::string> local_symbols(const fs::path& archive) {
  std::string out;
  if (pt::grade::run_command({"nm", "--defined-only", archive.string()}, &out) != 0 &&
      pt::grade::run_command({"llvm-nm", "--defined-only", archive.string()}, &out) != 0)
    return {"(unreadable: neither nm nor llvm-nm lists its symbols)"};
  std::vector<std::string> found;
  for (const auto& line : lines_of(out)) {
    std::istringstream in(line);
    std::string address, type, name;
    if (!(in >> address >> type >> name) || type.size() != 1) continue;
    if (std::string("tdbrsg").find(type[0]) == std::string::npos || name.rfind(".L", 0) == 0) continue;
    found.push_back(name);
  }
  return found;
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
    static const std::vector<std::string> banned = {"/reference/", "tests/mutants", "autograder/hostile", "/hidden/",
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
    if (is_text(bytes) && read_by_students(rel))
      for (const auto& m : missing_paths(rel, bytes, release)) findings.push_back(m);
    if (rel.rfind("scenes/reference/", 0) == 0 && fs::path(rel).extension() == ".json" &&
        std::regex_search(bytes, std::regex("[0-9a-f]{40}")))
      findings.push_back(rel + ": holds a commit hash (the instructor's repository's)");
    if (rel.rfind("prebuilt/", 0) == 0 && fs::path(rel).extension() == ".a") {
      const auto locals = local_symbols(path);
      if (!locals.empty())
        findings.push_back(rel + ": keeps " + std::to_string(locals.size()) + " local symbol(s), e.g. " + locals[0] +
                           " (strip -x)");
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
