#pragma once
// Where the handouts explain what a graded test checks, so that a report can
// send a student from a failure to the right section: the section of each
// task (the heading that names it, "## 3. Triangle intersection (P1T3)", or
// else the section whose table has its `TODO(PnTm)` row), and each test's row
// of its part's grading table (which names every test, hidden ones too).
#include <map>
#include <string>

namespace pt::grade {

struct HandoutRef {
  std::string file;     // handouts/part1.md
  std::string section;  // "3. Triangle intersection (P1T3): Möller–Trumbore"
};

struct HandoutIndex {
  std::map<std::string, HandoutRef> tasks;       // "P1T3" -> its section
  std::map<std::string, std::string> test_rows;  // "TriangleIntersect.Barycentrics" -> what its table row says
};

// Reads handouts/part*.md under `dir` (missing files give an empty index).
HandoutIndex index_handouts(const std::string& dir);

}  // namespace pt::grade
