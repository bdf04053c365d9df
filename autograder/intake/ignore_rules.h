#pragma once
// The patterns of a .gitignore, for check-submission: what a student's tools
// and the release's own instructions leave in the tree (a build folder,
// node_modules/ after `npm ci`, renders) is not a file "added" to the
// framework. A subset of git's rules, enough for the release's .gitignore:
// '#' comments, '!' negation (the last matching line wins), a trailing '/'
// for folders only, a pattern with a '/' anchored at the top (a leading '/'
// or '**/' aside), any other matched against each name in the path, and
// everything below an ignored folder ignored.
#include <string>
#include <vector>

namespace pt::grade {

class IgnoreRules {
 public:
  static IgnoreRules parse(const std::string& gitignore_text);
  static IgnoreRules read(const std::string& gitignore_path);  // none when the file is missing

  // `path`: relative to the .gitignore's folder, with '/' between names.
  bool ignored(const std::string& path, bool is_folder) const;

 private:
  struct Rule {
    std::string glob;
    bool negated = false, folders_only = false, anchored = false;
  };
  bool matches_itself(const std::string& path, bool is_folder) const;
  std::vector<Rule> rules_;
};

}  // namespace pt::grade
