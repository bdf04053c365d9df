// The score table a student reads in a terminal: a long failure message is
// folded, never cut (the camera test's diagnosis was once its 7th line),
// and hidden points a build could not run are shown as not run.
#include <gtest/gtest.h>

#include <string>

#include "report/report.h"

namespace pt::grade {
namespace {

// The text back from folded(): indents and the folds taken out.
std::string unfolded(const std::string& text, const std::string& indent) {
  std::string out, line;
  for (size_t pos = 0; pos < text.size();) {
    const size_t end = text.find('\n', pos);
    line = text.substr(pos, end - pos);
    pos = end + 1;
    EXPECT_EQ(line.rfind(indent, 0), 0u) << line;
    const bool continuation = line.rfind(indent + "  ", 0) == 0;
    out += (out.empty() || continuation ? "" : "\n") + line.substr(indent.size() + (continuation ? 2 : 0));
  }
  return out;
}

TEST(ReportText, FoldingKeepsEveryCharacterAndBoundsTheWidth) {
  std::string message = "Camera.GeneratesRayThroughPixelCentre failed:\n";
  for (int i = 0; i < 12; ++i) message += "line " + std::to_string(i) + ": expected (0.1, 0.2, -1) got (0.3, 0.4, -1)\n";
  message += "diagnosis: " + std::string(250, 'x') + " and " + std::string(30, 'y') + " words after a long one";
  const std::string out = folded(message, "    ", 60);
  EXPECT_EQ(unfolded(out, "    "), message);
  for (size_t pos = 0; pos < out.size();) {
    const size_t end = out.find('\n', pos);
    EXPECT_LE(end - pos, 4u + 2u + 60u) << out.substr(pos, end - pos);
    pos = end + 1;
  }
  EXPECT_NE(out.find("line 11:"), std::string::npos);
  EXPECT_EQ(out.find("more lines"), std::string::npos);
}

TEST(ReportText, TrailingNewlinesAndEmptyMessages) {
  EXPECT_EQ(folded("", "  "), "");
  EXPECT_EQ(folded("a\n\n", "  "), "  a\n");
  EXPECT_EQ(folded("a\n\nb", "  "), "  a\n  \n  b\n");
}

TEST(ReportText, HiddenPointsNotRunAreInTheTable) {
  Report report;
  PartResult part = pending_part(1, {{"Camera.A", "P1T1", 2, false}, {"Camera.B", "P1T1", 1, false}}, "");
  part.graded = true;
  part.tests[0].status = TestResult::Status::Passed;
  part.tests[1].status = TestResult::Status::Failed;
  part.tests[1].message = std::string(300, 'm');  // a line longer than the old cut at 240 characters
  for (int i = 2; i <= 8; ++i) part.tests[1].message += "\nline " + std::to_string(i);
  part.tests[1].message += "\nthe diagnosis, last";  // the old table cut after 6 lines
  report.parts.push_back(part);
  report.hidden_not_run[1] = {5, 6.5};
  testing::internal::CaptureStdout();
  print_report(report, false);
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("hidden: 5 tests, 6.5 points not run here"), std::string::npos) << out;
  EXPECT_NE(out.find("hidden: 6.5 points not run here"), std::string::npos) << out;
  EXPECT_NE(out.find("2 / 3"), std::string::npos) << out;
  EXPECT_NE(out.find("the diagnosis, last"), std::string::npos) << out;
  EXPECT_NE(out.find(std::string(60, 'm')), std::string::npos) << out;
  EXPECT_EQ(out.find("more lines"), std::string::npos) << out;
}

}  // namespace
}  // namespace pt::grade
