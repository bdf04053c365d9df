#include "intake/ignore_rules.h"

#include <fnmatch.h>

#include <fstream>
#include <sstream>

namespace pt::grade {

IgnoreRules IgnoreRules::parse(const std::string& text) {
  IgnoreRules r;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r' || line.back() == '\t')) line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    Rule rule;
    if (line[0] == '!') {
      rule.negated = true;
      line.erase(0, 1);
    }
    if (!line.empty() && line.back() == '/') {
      rule.folders_only = true;
      line.pop_back();
    }
    if (line.rfind("**/", 0) == 0) {
      line.erase(0, 3);  // at any depth: as a name, unless more '/' follow
    } else if (line.find('/') != std::string::npos) {
      rule.anchored = true;
      if (line[0] == '/') line.erase(0, 1);
    }
    if (line.empty()) continue;
    rule.glob = line;
    if (rule.glob.find('/') != std::string::npos) rule.anchored = true;
    r.rules_.push_back(rule);
  }
  return r;
}

IgnoreRules IgnoreRules::read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str());
}

bool IgnoreRules::matches_itself(const std::string& path, bool is_folder) const {
  const std::string name = path.substr(path.rfind('/') + 1);  // npos + 1 == 0
  bool ignored = false;
  for (const Rule& rule : rules_) {
    if (rule.folders_only && !is_folder) continue;
    const std::string& subject = rule.anchored ? path : name;
    if (fnmatch(rule.glob.c_str(), subject.c_str(), FNM_PATHNAME) == 0) ignored = !rule.negated;
  }
  return ignored;
}

bool IgnoreRules::ignored(const std::string& path, bool is_folder) const {
  // git does not look inside an ignored folder: nothing below it comes back.
  for (size_t slash = path.find('/'); slash != std::string::npos; slash = path.find('/', slash + 1))
    if (matches_itself(path.substr(0, slash), true)) return true;
  return matches_itself(path, is_folder);
}

}  // namespace pt::grade
