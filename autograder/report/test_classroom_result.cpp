// The GitHub Classroom result (classroom_result.h) in the cases a release's
// run does not reach: a part that did not build, an extension left undone,
// a check that found something the grader will do otherwise, messages far
// past the size an environment variable holds. (release:github-classroom
// checks the stubs' and the reference's results field by field.)
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "report/classroom_result.h"

namespace pt::grade {
namespace {

using nlohmann::json;

ManifestTest test(const std::string& name, const std::string& task, double points, bool extension = false) {
  ManifestTest t;
  t.name = name;
  t.task = task;
  t.points = extension ? 0 : points;
  t.extension = extension;
  return t;
}

PartResult graded(int part, const PartManifest& tests, std::initializer_list<TestResult::Status> statuses) {
  PartResult r = pending_part(part, tests, "");
  r.graded = true;
  auto s = statuses.begin();
  for (auto& t : r.tests) {
    t.status = *s++;
    if (!t.passed()) t.message = "Expected: 1\n  Actual: 2";
  }
  return r;
}

const json* named(const json& doc, const std::string& prefix) {
  for (const auto& t : doc["tests"])
    if (t["name"].get<std::string>().rfind(prefix, 0) == 0) return &t;
  return nullptr;
}

TEST(ClassroomResult, AnUndoneExtensionNeitherCountsNorFailsTheRun) {
  Report report;
  report.parts.push_back(graded(5, {test("A.One", "P5T1", 1.5), test("B.Two", "P5T3", 1, true)},
                                {TestResult::Status::Passed, TestResult::Status::Failed}));
  const json doc = json::parse(classroom_result(report, {}, {}, {}));
  EXPECT_EQ(doc["status"], "pass");
  EXPECT_EQ(doc["max_score"], 1.5);
  const json* ext = named(doc, "P5T3");
  ASSERT_NE(ext, nullptr);
  EXPECT_EQ((*ext)["status"], "fail");
  EXPECT_EQ((*ext)["score"], 0.0);
  EXPECT_NE((*ext)["name"].get<std::string>().find("(extension, not counted)"), std::string::npos);
}

TEST(ClassroomResult, APartThatDidNotBuildIsAnErrorForEachTaskAndFailsTheRun) {
  Report report;
  report.parts.push_back(pending_part(3, {test("S.A", "P3T1", 2), test("S.B", "P3T2", 1)},
                                      "tasks/part3_direct_lighting.cpp does not build: part 3 scores 0."));
  report.hidden_not_run[3] = {4, 3.5};
  const json doc = json::parse(classroom_result(report, {}, {}, {"part 3: does not build (step 4)"}));
  EXPECT_EQ(doc["status"], "fail");
  EXPECT_EQ(doc["max_score"], 3.0) << "the visible points only";
  for (const char* task : {"P3T1", "P3T2"}) {
    const json* t = named(doc, task);
    ASSERT_NE(t, nullptr) << task;
    EXPECT_EQ((*t)["status"], "error");
    EXPECT_NE((*t)["message"].get<std::string>().find("does not build"), std::string::npos);
  }
  const json* hidden = named(doc, "Part 3 hidden tests: not run here (4 tests, 3.5 points)");
  ASSERT_NE(hidden, nullptr);
  EXPECT_EQ((*hidden)["status"], "error");
  EXPECT_EQ((*hidden)["score"], 0.0);
  const json* verdict = named(doc, "pt-grade check-submission: NOT READY");
  ASSERT_NE(verdict, nullptr);
  EXPECT_EQ((*verdict)["status"], "fail");
  EXPECT_NE((*verdict)["message"].get<std::string>().find("does not build (step 4)"), std::string::npos);
}

TEST(ClassroomResult, HugeMessagesStayWithinWhatAnEnvironmentVariableHolds) {
  PartManifest tests;
  for (int i = 0; i < 150; ++i) tests.push_back(test("Suite.T" + std::to_string(i), "P1T" + std::to_string(i % 40), 1));
  Report report;
  report.parts.push_back(pending_part(1, tests, ""));
  report.parts.back().graded = true;
  for (auto& t : report.parts.back().tests) {
    t.status = TestResult::Status::Failed;
    t.message = std::string(100000, 'x') + "\xc3\xa9\xff\x01\n";  // long, non-ASCII, bad UTF-8, a control byte
  }
  const std::string text = classroom_result(report, {}, {}, {std::string(200000, 'p')});
  EXPECT_LE(text.size(), kMaxClassroomBytes);
  for (unsigned char c : text) ASSERT_TRUE(c < 0x80) << "not ASCII";
  const json doc = json::parse(text);
  EXPECT_EQ(doc["status"], "fail");
  EXPECT_EQ(doc["max_score"], 150.0);
  EXPECT_EQ(doc["tests"].size(), 41u) << "forty tasks and the verdict";
}

TEST(ClassroomResult, ACheckThatStoppedSaysWhyWithTheVisiblePoints) {
  const json doc = json::parse(classroom_stopped("fail", "The files", "part9_x.cpp: not a task file", 84.5));
  EXPECT_EQ(doc["version"], 1);
  EXPECT_EQ(doc["status"], "fail");
  EXPECT_EQ(doc["max_score"], 84.5);
  ASSERT_EQ(doc["tests"].size(), 1u);
  const json& t = doc["tests"][0];
  for (const char* field : {"name", "status", "score", "message", "test_code", "filename", "line_no", "duration"})
    EXPECT_TRUE(t.contains(field)) << field;
  EXPECT_EQ(t["message"], "part9_x.cpp: not a task file");
}

}  // namespace
}  // namespace pt::grade
