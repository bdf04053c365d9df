#include "report/handout_index.h"

#include <filesystem>
#include <fstream>
#include <regex>

namespace pt::grade {

namespace fs = std::filesystem;

HandoutIndex index_handouts(const std::string& dir) {
  HandoutIndex index;
  const std::regex task_tag(R"(P[0-9]+T[0-9]+)");
  const std::regex todo_tag(R"(`TODO\((P[0-9]+T[0-9]+)\)`)");
  const std::regex test_name(R"(`([A-Za-z0-9_]+\.[A-Za-z0-9_]+)`)");
  const std::regex last_cell(R"(\|\s*([^|]*?)\s*\|[^|]*$)");
  for (int part = 1; part <= 9; ++part) {
    const fs::path file = fs::path(dir) / ("part" + std::to_string(part) + ".md");
    std::ifstream in(file);
    if (!in) continue;
    const std::string rel = "handouts/" + file.filename().string();
    std::string section;
    std::map<std::string, std::string> from_table;  // task -> section of its TODO row
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("## ", 0) == 0) {
        // The heading as a reader sees it: a `TODO(PnTm)` tag in it (code to
        // grep for) reads as its task id.
        section = std::regex_replace(line.substr(3), todo_tag, "$1");
        for (std::sregex_iterator it(section.begin(), section.end(), task_tag), end; it != end; ++it)
          index.tasks.emplace(it->str(), HandoutRef{rel, section});
        continue;
      }
      if (line.rfind("| `TODO(", 0) == 0) {
        std::smatch m;
        if (std::regex_search(line, m, task_tag)) from_table.emplace(m.str(), section);
      }
      // A grading table row: | `Suite.Name` | task | points | visible | what it checks |
      if (line.rfind("| `", 0) == 0) {
        std::smatch m, cell;
        if (std::regex_search(line, m, test_name) && m.position(0) <= 2 && std::regex_search(line, cell, last_cell))
          index.test_rows.emplace(m[1].str(), cell[1].str());
      }
    }
    for (const auto& [task, sec] : from_table) index.tasks.emplace(task, HandoutRef{rel, sec});
  }
  return index;
}

}  // namespace pt::grade
