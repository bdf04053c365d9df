#include "report/check_answer.h"

#include <cstdio>
#include <regex>
#include <set>

#include "report/report_text.h"

namespace pt::grade {

std::string task_file_state(const std::string& text) {
  const std::string code = std::regex_replace(std::regex_replace(text, std::regex(R"(/\*[\s\S]*?\*/)"), ""),
                                              std::regex(R"(//[^\n]*)"), "");
  const std::regex thrown(R"(throw\s+(?:pt::)?NotImplemented\s*\(\s*"(P[0-9]+T[0-9]+))");
  std::set<std::string> tasks;
  for (std::sregex_iterator it(code.begin(), code.end(), thrown), end; it != end; ++it) tasks.insert((*it)[1].str());
  if (tasks.empty() && !std::regex_search(code, std::regex(R"(throw\s+(?:pt::)?NotImplemented)"))) return "yours";
  return "started: " + (tasks.empty() ? std::string("a task") : joined(tasks, ", ")) + " still throw" +
         (tasks.size() == 1 ? "s" : "") + " NotImplemented";
}

bool untouched(const PartResult& part) {
  if (!part.graded || part.tests.empty()) return false;
  for (const auto& t : part.tests)
    if (t.passed() || t.message.find("not implemented: P") == std::string::npos) return false;
  return true;
}

void print_answer(const std::vector<PartAnswer>& parts, const std::vector<std::string>& problems, bool as_grader) {
  std::printf("\n%-5s %-46s %-16s %s\n", "part", "task file", "visible points", "at grading");
  for (const auto& p : parts) {
    std::vector<std::string> at_grading;
    if (!p.differs.empty()) at_grading.push_back(p.differs);
    if (p.hidden.tests > 0) at_grading.push_back("+ hidden: " + p.hidden.text() + " not run here");
    const std::string score = points_number(p.earned) + " / " + points_number(p.possible);
    std::printf("%-5d %-46s %-16s %s\n", p.part, p.state.c_str(), score.c_str(), joined(at_grading, "; ").c_str());
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
