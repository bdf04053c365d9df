#include "report/classroom_result.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include <nlohmann/json.hpp>

#include "report/report_text.h"

namespace pt::grade {
namespace {

using nlohmann::json;

json entry(const std::string& name, const std::string& status, double score, const std::string& message,
           const std::string& test_code = "", const std::string& filename = "", int line_no = 0, double seconds = 0) {
  return {{"name", name},           {"status", status},         {"score", score},
          {"message", message},     {"test_code", test_code},   {"filename", filename},
          {"line_no", line_no},     {"duration", static_cast<long>(std::lround(seconds * 1000))}};
}

// "P1T3 Triangle intersection: Möller–Trumbore" from the handout's heading
// "3. Triangle intersection (P1T3): Möller–Trumbore"; the id alone without one.
std::string task_title(const std::string& task, const HandoutIndex& handouts) {
  const auto it = handouts.tasks.find(task);
  if (it == handouts.tasks.end()) return task;
  std::string title = std::regex_replace(it->second.section, std::regex(R"(^[0-9]+\.\s*)"), "");
  const std::string tag = " (" + task + ")";
  if (const auto at = title.find(tag); at != std::string::npos) title.erase(at, tag.size());
  return task + " " + title;
}

// The line of the task's TODO tag in the student's file (else of its id): 0
// when neither is left.
int line_of(const std::string& task, const std::string& text) {
  size_t at = text.find("TODO(" + task + ")");
  if (at == std::string::npos) at = text.find(task);
  if (at == std::string::npos) return 0;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

struct Task {
  std::string id;
  std::vector<const TestResult*> tests;  // visible ones, manifest order
};

json task_entry(const Task& task, const PartResult& part, const ClassroomFile* file, const HandoutIndex& handouts,
                size_t message_cap) {
  Tally tally;
  double seconds = 0;
  std::vector<std::string> names;
  std::string failures;
  bool counted = false;
  for (const TestResult* t : task.tests) {
    tally.add(*t);
    seconds += t->seconds;
    counted = counted || !t->test.uncounted();
    names.push_back(t->test.name);
    if (t->passed()) continue;
    failures += "\n" + t->test.name + " (" + points_number(t->test.points) + "): " +
                summary(t->message, "./build/tests/part" + std::to_string(part.part) + "_tests shows all of it");
  }
  std::string name = task_title(task.id, handouts) + ": " + tally.points() + (tally.possible == 1 ? " point" : " points");
  if (!counted) name += " (extension, not counted)";
  const int n = tally.total, failed = n - tally.passed;
  std::string message;
  if (!part.graded)
    message = "not graded: " + (task.tests.empty() ? std::string() : task.tests.front()->message);
  else if (failed == 0)
    message = "its " + std::to_string(n) + " visible test" + (n == 1 ? "" : "s") + " passed";
  else
    message = std::to_string(failed) + " of its " + std::to_string(n) + " visible tests failed:" + failures;
  if (const auto it = handouts.tasks.find(task.id); it != handouts.tasks.end())
    message += "\n(" + it->second.file + ", section \"" + it->second.section + "\")";
  const std::string status = !part.graded ? "error" : failed == 0 ? "pass" : "fail";
  return entry(name, status, tally.earned, capped(message, message_cap),
               "./build/tests/part" + std::to_string(part.part) + "_tests --gtest_filter=" + joined(names, ":"),
               file ? file->path : "", file ? line_of(task.id, file->text) : 0, seconds);
}

json document(const Report& report, const std::map<int, ClassroomFile>& files, const HandoutIndex& handouts,
              const std::vector<std::string>& problems, size_t message_cap) {
  json tests = json::array();
  double max_score = 0;
  bool all_passed = true;
  for (const auto& part : report.parts) {
    std::map<int, Task> tasks;  // by number: the handout's order (P1T1, P1T2, ...), not the manifest's
    for (const auto& t : part.tests) {
      if (t.test.hidden) continue;  // not in a release; an instructor's checkout lists them in its manifest
      max_score += t.test.points;
      all_passed = all_passed && (t.passed() || t.test.uncounted());
      Task& task = tasks[std::stoi(t.test.task.substr(t.test.task.find('T') + 1))];
      task.id = t.test.task;
      task.tests.push_back(&t);
    }
    const auto file = files.find(part.part);
    for (const auto& [number, task] : tasks)
      tests.push_back(task_entry(task, part, file == files.end() ? nullptr : &file->second, handouts, message_cap));
    if (const auto h = report.hidden_not_run.find(part.part); h != report.hidden_not_run.end() && h->second.tests > 0) {
      tests.push_back(entry("Part " + std::to_string(part.part) + " hidden tests: not run here (" + h->second.text() + ")", "error",
                            0,
                            "The course's grader runs these when you submit; this repository does not hold them. "
                            "handouts/part" + std::to_string(part.part) +
                                ".md's grading table says what each one checks."));
    }
  }
  std::string verdict;
  for (const auto& p : problems) verdict += "\n- " + p;
  tests.push_back(problems.empty()
                      ? entry("pt-grade check-submission: READY", "pass", 0,
                              "The grader will build and run these files as this check did.",
                              "./build/autograder/pt-grade check-submission")
                      : entry("pt-grade check-submission: NOT READY", "fail", 0,
                              capped("The grader's result will differ from this check's:" + verdict, message_cap),
                              "./build/autograder/pt-grade check-submission"));
  return {{"version", 1},
          {"status", all_passed && problems.empty() ? "pass" : "fail"},
          {"max_score", max_score},
          {"tests", tests}};
}

// ASCII (the reporter's decoder and an environment variable take it whole),
// bad UTF-8 from a test's message replaced.
std::string text_of(const json& doc) { return doc.dump(-1, ' ', true, json::error_handler_t::replace) + "\n"; }

}  // namespace

std::string classroom_result(const Report& report, const std::map<int, ClassroomFile>& files,
                             const HandoutIndex& handouts, const std::vector<std::string>& problems) {
  // Each message within a cap, halved until the whole fits.
  for (size_t cap = 4096;; cap /= 2) {
    const std::string text = text_of(document(report, files, handouts, problems, cap));
    if (text.size() <= kMaxClassroomBytes || cap <= 64) return text;
  }
}

std::string classroom_stopped(const std::string& status, const std::string& what, const std::string& why,
                              double visible_points) {
  const json doc = {{"version", 1},
                    {"status", status},
                    {"max_score", visible_points},
                    {"tests", json::array({entry(what, status, 0, capped(why, kMaxClassroomBytes / 2),
                                                 "./build/autograder/pt-grade check-submission")})}};
  return text_of(doc);
}

}  // namespace pt::grade
