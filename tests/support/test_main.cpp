// Main of every test binary. Beyond GoogleTest's own flags it understands
//   --pt_list_graded          print the graded tests (JSON lines) and exit
//   --pt_results=FILE         append one JSON line per finished test to FILE,
//                             flushed at once, so a grader keeps the results of
//                             the tests that ran before a crash or a hang
//   --pt_seed=N               seed offset for statistical tests (see seed.h)
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/graded.h"
#include "support/seed.h"

namespace pt::grading {

std::vector<GradedTest>& registry() {
  static std::vector<GradedTest> tests;
  return tests;
}

bool register_test(const char* suite, const char* name, const char* task, double points, Visibility v) {
  registry().push_back({suite, name, task, points, v});
  return true;
}

const GradedTest* find(const std::string& suite, const std::string& name) {
  for (const auto& t : registry())
    if (t.suite == suite && t.name == name) return &t;
  return nullptr;
}

namespace {

nlohmann::json describe(const GradedTest& t) {
  return {{"test", t.full_name()},
          {"task", t.task},
          {"points", t.points},
          {"visibility", t.visibility == Visibility::Visible ? "visible" : "hidden"}};
}

// Records the grading properties at the start of each test and streams each
// result as it ends.
class GradingListener : public testing::EmptyTestEventListener {
 public:
  explicit GradingListener(std::string path) : path_(std::move(path)) {}

  void OnTestStart(const testing::TestInfo& info) override {
    if (const GradedTest* g = find(info.test_suite_name(), info.name())) {
      testing::Test::RecordProperty("task", g->task);
      testing::Test::RecordProperty("points", std::to_string(g->points));
      testing::Test::RecordProperty("visibility", g->visibility == Visibility::Visible ? "visible" : "hidden");
    }
  }

  void OnTestEnd(const testing::TestInfo& info) override {
    if (path_.empty()) return;
    const testing::TestResult& r = *info.result();
    std::string messages;
    for (int i = 0; i < r.total_part_count(); ++i) {
      const auto& part = r.GetTestPartResult(i);
      if (part.failed()) {
        if (!messages.empty()) messages += "\n";
        if (part.file_name()) messages += std::string(part.file_name()) + ":" + std::to_string(part.line_number()) + ": ";
        messages += part.message();
      }
    }
    nlohmann::json line = {{"test", std::string(info.test_suite_name()) + "." + info.name()},
                           {"passed", r.Passed()},
                           {"skipped", r.Skipped()},
                           {"seconds", r.elapsed_time() / 1000.0},
                           {"message", messages}};
    if (const GradedTest* g = find(info.test_suite_name(), info.name())) line.update(describe(*g));
    // A student message may hold invalid UTF-8; replace it rather than throw
    // inside the listener, which would abort the binary.
    std::ofstream(path_, std::ios::app) << line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n"
                                        << std::flush;
  }

 private:
  std::string path_;
};

}  // namespace
}  // namespace pt::grading

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  std::string results_path;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--pt_list_graded") == 0) {
      for (const auto& t : pt::grading::registry()) std::cout << pt::grading::describe(t).dump() << "\n";
      return 0;
    }
    if (std::strncmp(argv[i], "--pt_results=", 13) == 0) results_path = argv[i] + 13;
    if (std::strncmp(argv[i], "--pt_seed=", 10) == 0) pt::test::set_seed_offset(std::strtoull(argv[i] + 10, nullptr, 10));
  }
  testing::UnitTest::GetInstance()->listeners().Append(new pt::grading::GradingListener(results_path));
  return RUN_ALL_TESTS();
}
