#include "run/checks.h"

#include <cstdio>

namespace pt::grade {
namespace {

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

}  // namespace

int check_stubs(const PartResult& r) {
  const std::string wanted = "not implemented: P" + std::to_string(r.part) + "T";
  std::vector<std::string> problems;
  if (r.tests.empty()) problems.push_back("the manifest lists no graded test for part " + std::to_string(r.part));
  for (const auto& t : r.tests) {
    const std::string what = t.test.name + " (" + t.test.task + "): ";
    if (t.passed())
      problems.push_back(what + "passed");
    else if (t.status != TestResult::Status::Failed)
      problems.push_back(what + t.status_name() + ": " + first_line(t.message) + " (the stubs must neither crash nor hang)");
    else if (t.message.find(wanted) == std::string::npos)
      problems.push_back(what + "fails without \"" + wanted + "\": " + first_line(t.message));
  }
  if (problems.empty()) {
    std::printf("stubs OK: all %zu graded tests of part %d fail with \"%s...\"\n", r.tests.size(), r.part,
                wanted.c_str());
    return 0;
  }
  std::printf("stubs check failed for %s:\n", r.binary.c_str());
  for (const auto& p : problems) std::printf("  %s\n", p.substr(0, 400).c_str());
  for (const auto& n : r.notes) std::printf("  note: %s\n", n.c_str());
  if (!r.log.empty()) std::printf("(output: %s)\n", r.log.c_str());
  return 1;
}

int check_mutant(const PartResult& r) {
  std::vector<const TestResult*> caught;
  for (const auto& t : r.tests)
    if (t.status == TestResult::Status::Failed || t.status == TestResult::Status::NoVerdict || t.died())
      caught.push_back(&t);
  if (caught.empty()) {
    std::printf("mutant survived: no graded test failed (%zu graded tests)\n", r.tests.size());
    for (const auto& n : r.notes) std::printf("  note: %s\n", n.c_str());
    return 1;
  }
  std::printf("mutant caught by %zu of %zu graded tests:\n", caught.size(), r.tests.size());
  for (const auto* t : caught)
    std::printf("  %s %s: %s\n", t->test.task.c_str(), t->test.name.c_str(), first_line(t->message).substr(0, 200).c_str());
  return 0;
}

}  // namespace pt::grade
