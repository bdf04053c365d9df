// Reports have a size whatever a submission does (report_text.h): each text is
// cut at its bound with a note, a long part-level reason is said once, and
// results.json, Gradescope's and PrairieLearn's, stays within kMaxResultsBytes
// for any number of huge messages (and renders).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "report/prairielearn_report.h"
#include "report/report.h"
#include "report/report_text.h"

namespace pt::grade {
namespace {

// What JSON makes of each kind of character, against nlohmann's own dump.
TEST(ReportBounds, JsonCostIsWhatTheDumpTakes) {
  const std::string text = std::string("plain \"quoted\" back\\slash\n\t") + '\x01' + '\x1b' + "\xff" + "\xc3\xa9" +
                           "\xe2\x80\xae" + std::string(1, '\xc3');
  const std::string dumped =
      nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  EXPECT_EQ(json_cost(text), dumped.size() - 2);
}

TEST(ReportBounds, ACappedTextFitsAndSaysWhatWasCut) {
  std::string text;
  for (int i = 0; i < 100000; ++i) text += "\"\\\x01\xff";
  const std::string cut = capped(text, 4096);
  EXPECT_LE(json_cost(cut), 4096u);
  EXPECT_NE(cut.find("pt-grade cut"), std::string::npos);
  EXPECT_NE(cut.find(std::to_string(text.size()) + " bytes"), std::string::npos);
  EXPECT_EQ(capped("short", 4096), "short");
  // Never half a character: a cut inside a 3-byte character keeps none of it.
  const std::string wide = capped(std::string(2000, '\xe2') + "", 300);
  EXPECT_LE(json_cost(wide), 300u);
}

TEST(ReportBounds, ASummaryIsShortAndItsOwnSummary) {
  std::string reason = "part1.cpp rejected before building:\n";
  for (int i = 0; i < 5000; ++i) reason += "part1.cpp:" + std::to_string(i) + ": #embed refused\n";
  const std::string once = summary(reason, "the rest is in the notes");
  EXPECT_LE(json_cost(once), kSummaryBytes);
  EXPECT_NE(once.find("rejected before building"), std::string::npos);
  EXPECT_NE(once.find("the rest is in the notes"), std::string::npos);
  EXPECT_EQ(summary(once, "the rest is in the notes"), once);
  EXPECT_EQ(summary("one line", "x"), "one line");
}

TEST(ReportBounds, ALongListKeepsItsHeadAndCountsTheRest) {
  std::vector<std::string> items(10000, std::string(2000, 'f'));
  const std::string text = capped_list(items, 100, 512);
  EXPECT_LE(text.size(), 100u * 600u);
  EXPECT_NE(text.find("and 9900 more"), std::string::npos);
}

// A part-level reason goes to the part's notes once, not into every test.
TEST(ReportBounds, APartLevelReasonIsNotCopiedIntoEveryTest) {
  PartManifest tests;
  for (int i = 0; i < 40; ++i) tests.push_back({"Suite.Test" + std::to_string(i), "P1T1", 0.5, false, false});
  std::string why = "part1.cpp rejected before building:\n";
  for (int i = 0; i < 20000; ++i) why += "part1.cpp:" + std::to_string(i) + ": refused\n";
  const PartResult r = pending_part(1, tests, why);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0], why);
  for (const auto& t : r.tests) EXPECT_LE(t.message.size(), kSummaryBytes);
}

// 500 tests, each with 64 KiB of the costliest characters (384 KiB of JSON) in
// its message and output, and notes: 380 MB uncapped.
Report costly_report() {
  const std::string costly(64 << 10, '\x01');
  Report report;
  PartResult part;
  part.part = 1;
  for (int i = 0; i < 500; ++i) {
    TestResult t;
    t.test = {"Suite.Test" + std::to_string(i), "P1T1", 0.5, i % 2 == 0, false};
    t.status = TestResult::Status::Failed;
    t.message = costly;
    t.output = costly;
    part.tests.push_back(t);
    part.notes.push_back(costly);
  }
  report.parts.push_back(part);
  report.notes.push_back(costly);
  return report;
}

TEST(ReportBounds, ResultsJsonFitsWhateverTheMessages) {
  const Report report = costly_report();
  const std::string path = ::testing::TempDir() + "pt_report_bounds.json";
  write_results_json(path, report);
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_LE(s.str().size(), kMaxResultsBytes);
  const auto doc = nlohmann::json::parse(s.str());
  EXPECT_EQ(doc["tests"].size(), 500u);  // every test listed
  EXPECT_NE(doc["tests"][0]["output"].get<std::string>().find("pt-grade cut"), std::string::npos);
  std::remove(path.c_str());
}

// A 256x192 PNG of noise (it compresses to nothing: about 150 KB), the
// worst a render can be.
std::string noise_png(const std::string& name, unsigned seed) {
  std::vector<unsigned char> pixels(256 * 192 * 3);
  for (auto& p : pixels) p = static_cast<unsigned char>((seed = seed * 1664525u + 1013904223u) >> 24);
  const std::string path = ::testing::TempDir() + name;
  stbi_write_png(path.c_str(), 256, 192, 3, pixels.data(), 256 * 3);
  return path;
}

// The costly report again with 20 scenes of noise: PrairieLearn's file
// keeps every test, shows what images fit at half size within their bound,
// says how many it left out, and stays within 1 MB.
TEST(ReportBounds, PrairieLearnResultsFitWhateverTheMessagesAndRenders) {
  const Report report = costly_report();
  HtmlReport page;
  page.report = &report;
  const std::string student = noise_png("pt_noise_a.png", 1), reference = noise_png("pt_noise_b.png", 2);
  for (int i = 0; i < 20; ++i) {
    RenderComparison c;
    c.scene = "scene" + std::to_string(i);
    c.student_png = student;
    c.reference_png = reference;
    c.student_parts = {1};
    page.renders.push_back(c);
  }
  const std::string text = prairielearn_json(page);
  EXPECT_LE(text.size(), kMaxResultsBytes);
  const auto doc = nlohmann::json::parse(text);
  EXPECT_TRUE(doc["gradable"].get<bool>());
  EXPECT_EQ(doc["tests"].size(), 500u);
  size_t image_bytes = 0;
  for (const auto& image : doc["images"]) image_bytes += image["url"].get<std::string>().size();
  EXPECT_GT(doc["images"].size(), 0u);
  EXPECT_LE(image_bytes, kMaxImageBytes);
  const std::string output = doc["output"];
  EXPECT_NE(output.find("1/2 of their size"), std::string::npos) << output.substr(output.size() - 500);
  EXPECT_NE(output.find(std::to_string(20 - doc["images"].size() / 2) + " scene(s) rendered but not shown"),
            std::string::npos);
  std::remove(student.c_str());
  std::remove(reference.c_str());
}

// A submission refused as a whole: not gradable, why, and no list of zeros.
TEST(ReportBounds, PrairieLearnRefusedSubmissionIsNotGradable) {
  Report report = costly_report();
  report.ungradable = "submission rejected before building:\n  no task file found in /grade/student";
  HtmlReport page;
  page.report = &report;
  const auto doc = nlohmann::json::parse(prairielearn_json(page));
  EXPECT_FALSE(doc["gradable"].get<bool>());
  EXPECT_EQ(doc["format_errors"][0].get<std::string>(), report.ungradable);
  EXPECT_TRUE(doc["tests"].empty());
  EXPECT_TRUE(doc["images"].empty());
}

// check-mutant --cheap-first reads each test's seconds back from a
// results.json; a file that is missing, not JSON or not ours reads as no times
// (the mutant's tests then run in their usual order).
TEST(ResultsTimes, EachTestsSecondsReadBackAsWritten) {
  Report report;
  PartResult part;
  part.part = 3;
  for (const double took : {0.125, 14.5}) {
    TestResult t;
    t.test = {"Suite.Took" + std::to_string(int(took * 1000)), "P3T3", 1, false, false};
    t.status = TestResult::Status::Passed;
    t.seconds = took;
    part.tests.push_back(t);
  }
  report.parts.push_back(part);
  const std::string path = ::testing::TempDir() + "pt_results_times.json";
  write_results_json(path, report);
  const auto seconds = test_seconds_from_results(path);
  ASSERT_EQ(seconds.size(), 2u);
  EXPECT_DOUBLE_EQ(seconds.at("Suite.Took125"), 0.125);
  EXPECT_DOUBLE_EQ(seconds.at("Suite.Took14500"), 14.5);
  for (const char* text : {"not json {", "[1, 2]", "{\"tests\": 3}", "{\"tests\": [{\"extra_data\": 1}]}"}) {
    std::ofstream(path, std::ios::trunc) << text;
    EXPECT_TRUE(test_seconds_from_results(path).empty()) << text;
  }
  std::remove(path.c_str());
  EXPECT_TRUE(test_seconds_from_results(path).empty());
}

}  // namespace
}  // namespace pt::grade
