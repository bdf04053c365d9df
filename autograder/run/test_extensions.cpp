// Extension tasks (P5T3): listed with "extension": true, graded at 0 points
// unless the instructor counts them, and said to be so in every report.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "report/report.h"
#include "run/manifest.h"

namespace pt::grade {
namespace {

const char* const kListing =
    R"({"test": "SampleAdaptively.A", "task": "P5T1", "points": 1.5, "visibility": "visible"})"
    "\n"
    R"({"test": "AllocateSamples.B", "task": "P5T3", "points": 1, "visibility": "hidden", "extension": true})"
    "\n";

double points_of(const PartManifest& tests) {
  double sum = 0;
  for (const auto& t : tests) sum += t.points;
  return sum;
}

TEST(Extensions, TheListingMarksThemAndTheManifestKeepsTheMark) {
  const PartManifest tests = parse_listing(5, kListing);
  ASSERT_EQ(tests.size(), 2u);
  EXPECT_FALSE(tests[0].extension);
  EXPECT_TRUE(tests[1].extension);
  EXPECT_EQ(tests[1].points, 1.0) << "the listing keeps the points they are worth when counted";

  const std::string path = (std::filesystem::temp_directory_path() / "pt_extensions_manifest.json").string();
  Manifest m;
  m.parts[5] = tests;
  write_manifest(path, m, {{5, "part5_tests_reference"}});
  Manifest back = read_manifest(path);
  std::remove(path.c_str());
  ASSERT_EQ(back.parts[5].size(), 2u);
  EXPECT_TRUE(back.parts[5][1].extension);
  EXPECT_EQ(points_of(back.parts[5]), 2.5);

  EXPECT_EQ(leave_extensions_uncounted(back), 1);
  EXPECT_EQ(back.parts[5][1].points, 0.0);
  EXPECT_EQ(back.parts[5][0].points, 1.5) << "only extension tests lose their points";
  EXPECT_EQ(points_of(back.parts[5]), 1.5);
}

TEST(Extensions, AMarkThatIsNotABooleanIsRefused) {
  EXPECT_THROW(parse_listing(5, R"({"test": "S.A", "task": "P5T3", "points": 1, "visibility": "visible", "extension": "yes"})"),
               std::runtime_error);
}

TEST(Extensions, ReportsSayTheyAreNotCounted) {
  Manifest m;
  m.parts[5] = parse_listing(5, kListing);
  leave_extensions_uncounted(m);
  Report report;
  PartResult part = pending_part(5, m.parts[5], "");
  part.graded = true;
  part.tests[0].status = TestResult::Status::Passed;
  part.tests[1].status = TestResult::Status::Failed;
  part.tests[1].message = "not implemented: P5T3 allocate_samples";
  report.parts.push_back(part);

  testing::internal::CaptureStdout();
  print_report(report, true);
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("1.5 / 1.5"), std::string::npos) << out;
  EXPECT_NE(out.find("extension tests, not counted: 0 / 1"), std::string::npos) << out;
  EXPECT_NE(out.find("an extension task, not counted"), std::string::npos) << out;

  const std::string path = (std::filesystem::temp_directory_path() / "pt_extensions_results.json").string();
  write_results_json(path, report);
  std::ifstream in(path);
  const nlohmann::json results = nlohmann::json::parse(in);
  std::remove(path.c_str());
  EXPECT_EQ(results.at("score").get<double>(), 1.5);
  bool seen = false;
  for (const auto& t : results.at("tests"))
    if (t.at("name").get<std::string>().find("AllocateSamples.B") != std::string::npos) {
      seen = true;
      EXPECT_EQ(t.at("max_score").get<double>(), 0.0) << t.dump();
      EXPECT_NE(t.at("name").get<std::string>().find("(extension, not counted)"), std::string::npos) << t.dump();
    }
  EXPECT_TRUE(seen) << results.dump(2);
}

}  // namespace
}  // namespace pt::grade
