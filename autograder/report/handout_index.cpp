#include "report/handout_index.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <vector>

namespace pt::grade {

namespace {

namespace fs = std::filesystem;

std::vector<std::string> cells_of(const std::string& row) {
  std::vector<std::string> cells;
  size_t pos = row.find('|');
  while (pos != std::string::npos) {
    const size_t next = row.find('|', pos + 1);
    if (next == std::string::npos) break;
    std::string c = row.substr(pos + 1, next - pos - 1);
    const auto b = c.find_first_not_of(' '), e = c.find_last_not_of(' ');
    cells.push_back(b == std::string::npos ? "" : c.substr(b, e - b + 1));
    pos = next;
  }
  return cells;
}

}  // namespace

HandoutIndex index_handouts(const std::string& dir) {
  HandoutIndex index;
  const std::regex task_tag(R"(P[0-9]+T[0-9]+)");
  const std::regex todo_tag(R"(`TODO\((P[0-9]+T[0-9]+)\)`)");
  const std::regex test_name(R"(`([A-Za-z0-9_]+\.[A-Za-z0-9_]+)`)");
  std::error_code ec;
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
        std::smatch m;
        if (std::regex_search(line, m, test_name) && m.position(0) <= 2) {
          const auto cells = cells_of(line);
          if (!cells.empty()) index.test_rows.emplace(m[1].str(), cells.back());
        }
      }
    }
    for (const auto& [task, sec] : from_table) index.tasks.emplace(task, HandoutRef{rel, sec});
  }
  return index;
}

}  // namespace pt::grade
