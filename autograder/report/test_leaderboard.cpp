// The leaderboard's entries from two runs' measurements (leaderboard.h):
// the SAH ratio is the geometric mean over the scenes the solution measured,
// and a submission that lacks one gets no entries. (submission:leaderboard
// measures the reference and a mutant end to end.)
#include <gtest/gtest.h>

#include <cmath>

#include "report/leaderboard.h"

namespace pt::grade {
namespace {

const std::map<std::string, double> kSolution = {
    {"sah_cost_mesh", 40}, {"sah_cost_fibres", 120}, {"primitive_tests_per_ray", 7}, {"node_visits_per_ray", 14}};

TEST(Leaderboard, TheSahRatioIsTheGeometricMeanOverTheScenes) {
  std::string why;
  const auto entries = leaderboard_entries({{"sah_cost_mesh", 80},
                                            {"sah_cost_fibres", 960},
                                            {"primitive_tests_per_ray", 68.57},
                                            {"node_visits_per_ray", 93.02}},
                                           kSolution, &why);
  ASSERT_EQ(entries.size(), 3u) << why;
  EXPECT_EQ(entries[0].name, "SAH cost / solution's");
  EXPECT_NEAR(entries[0].value, std::sqrt(2.0 * 8.0), 1e-3) << "2x on one scene, 8x on the other";
  EXPECT_EQ(entries[1].value, 68.57);
  EXPECT_EQ(entries[2].value, 93.02);
  for (const auto& e : entries) EXPECT_EQ(e.order, "asc") << e.name << ": smaller is better";
}

TEST(Leaderboard, TheSolutionAgainstItselfIsOne) {
  std::string why;
  const auto entries = leaderboard_entries(kSolution, kSolution, &why);
  ASSERT_EQ(entries.size(), 3u) << why;
  EXPECT_EQ(entries[0].value, 1.0);
}

TEST(Leaderboard, AMissingSceneOrCountGivesNoEntries) {
  auto student = kSolution;
  student.erase("sah_cost_fibres");
  std::string why;
  EXPECT_TRUE(leaderboard_entries(student, kSolution, &why).empty());
  EXPECT_NE(why.find("sah_cost_fibres"), std::string::npos) << why;
  student = kSolution;
  student.erase("node_visits_per_ray");
  EXPECT_TRUE(leaderboard_entries(student, kSolution, &why).empty());
  student = kSolution;
  student["sah_cost_mesh"] = 0;  // a tree of nothing
  EXPECT_TRUE(leaderboard_entries(student, kSolution, &why).empty());
}

}  // namespace
}  // namespace pt::grade
