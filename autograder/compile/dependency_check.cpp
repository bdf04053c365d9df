#include "compile/dependency_check.h"

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "process/command.h"

namespace pt::grade {

namespace fs = std::filesystem;

namespace {

// The files the compiler opened for each object of a build (ninja's record
// of its dependency output), the object's path as ninja names it -> the files.
std::map<std::string, std::vector<std::string>> dependency_record(const std::string& build_dir) {
  std::string out;
  run_command({"ninja", "-C", build_dir, "-t", "deps"}, &out);
  std::istringstream in(out);
  std::map<std::string, std::vector<std::string>> record;
  std::vector<std::string>* deps = nullptr;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    if (line[0] != ' ') {
      deps = &record[line.substr(0, line.find(':'))];
      continue;
    }
    if (!deps) continue;
    fs::path p = fs::path(line.substr(line.find_first_not_of(' ')));
    if (p.is_relative()) p = fs::path(build_dir) / p;
    deps->push_back(p.lexically_normal().string());
  }
  return record;
}

}  // namespace

std::vector<std::string> unexpected_dependencies(const std::string& build_dir, const std::string& object_marker,
                                                 const std::vector<std::string>& allowed,
                                                 const std::string& probe_marker) {
  const auto record = dependency_record(build_dir);
  std::set<std::string> probed;  // what the standard library and GLM open on this compiler
  std::vector<std::string> folders = allowed;
  if (!probe_marker.empty()) {
    for (const auto& [object, deps] : record)
      if (object.find(probe_marker) != std::string::npos) probed.insert(deps.begin(), deps.end());
    if (probed.empty())
      return {"(the standard library's list of files is missing: the kit's header probe was not built; an "
              "instructor must look)"};
    // GLM is header-only: any of its headers (<glm/gtx/...> too), wherever
    // this machine keeps it.
    for (const auto& d : probed)
      if (d.size() > 12 && d.compare(d.size() - 12, 12, "/glm/glm.hpp") == 0) folders.push_back(d.substr(0, d.size() - 7));
  }
  std::vector<std::string> unexpected;
  for (const auto& [object, deps] : record) {
    if (object.find(object_marker) == std::string::npos) continue;
    for (const auto& dep : deps) {
      bool ok = probed.count(dep) > 0;
      for (const auto& a : folders) ok = ok || dep.rfind(a, 0) == 0;
      if (ok) continue;
      const bool gtest = dep.find("/gtest/") != std::string::npos || dep.find("/gmock/") != std::string::npos;
      unexpected.push_back(dep + (gtest ? " (GoogleTest: the tests' framework, not a task file's)" : ""));
    }
  }
  return unexpected;
}

}  // namespace pt::grade
