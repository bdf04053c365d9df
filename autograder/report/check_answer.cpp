#include "report/check_answer.h"

#include <cstdio>
#include <regex>
#include <set>

namespace pt::grade {

std::string task_file_state(const std::string& text) {
  const std::string code = std::regex_replace(std::regex_replace(text, std::regex(R"(/\*[\s\S]*?\*/)"), ""),
                                              std::regex(R"(//[^\n]*)"), "");
  const std::regex thrown(R"(throw\s+(?:pt::)?NotImplemented\s*\(\s*"(P[0-9]+T[0-9]+))");
  std::set<std::string> tasks;
  bool any = false;
  for (std::sregex_iterator it(code.begin(), code.end(), thrown), end; it != end; ++it) {
    tasks.insert((*it)[1].str());
    any = true;
  }
  if (!any && std::regex_search(code, std::regex(R"(throw\s+(?:pt::)?NotImplemented)"))) any = true;
  if (!any) return "yours";
  std::string list;
  for (const auto& t : tasks) list += (list.empty() ? "" : ", ") + t;
  return "started: " + (list.empty() ? std::string("a task") : list) + " still throw" +
         (tasks.size() == 1 ? "s" : "") + " NotImplemented";
}

bool untouched(const PartResult& part) {
  if (!part.graded || part.tests.empty()) return false;
  for (const auto& t : part.tests)
    if (t.passed() || t.message.find("not implemented: P") == std::string::npos) return false;
  return true;
}

std::string points_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);  // points are given in hundredths
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

void print_answer(const std::vector<PartAnswer>& parts, const std::vector<std::string>& problems, bool as_grader) {
  std::printf("\n%-5s %-46s %-16s %s\n", "part", "task file", "visible points", "at grading");
  for (const auto& p : parts) {
    std::string at_grading = p.differs;
    if (p.hidden.tests > 0)
      at_grading += (at_grading.empty() ? "" : "; ") + std::string("+ hidden: ") + std::to_string(p.hidden.tests) +
                    " tests, " + points_number(p.hidden.points) + (p.hidden.points == 1 ? " point" : " points") +
                    " not run here";
    const std::string score = points_number(p.earned) + " / " + points_number(p.possible);
    std::printf("%-5d %-46s %-16s %s\n", p.part, p.state.c_str(), score.c_str(), at_grading.c_str());
  }
  if (problems.empty() && !as_grader) {
    std::printf("\nREADY, as far as this platform can check: the grader will build these files as this check did; "
                "it also runs them in its sandbox, across the process boundary, after pt-link-guard, and runs the "
                "hidden tests, none of which this check could do here.\n");
    return;
  }
  if (problems.empty()) {
    std::printf("\nREADY: the grader will build and run these files as this check did; it also runs the hidden "
                "tests, which this release does not have.\n");
    return;
  }
  std::printf("\nNOT READY: the grader's result will differ from this check's:\n");
  for (const auto& p : problems) std::printf("  - %s\n", p.c_str());
}

}  // namespace pt::grade
