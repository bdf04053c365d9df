// Not graded: the measurements behind the Part 2 leaderboard (pt-grade
// submission --leaderboard, autograder/report/leaderboard.h), work counted as the
// quality tests count it (support/bvh_checks.h), never time: on two fixed
// scenes, a mesh and the elongated fibres (where a split without a cost model
// is 5x the baseline's SAH cost), the tree's SAH cost, and the primitive
// tests and node visits per ray of the student's own closest-hit traversal.
// The grader runs it beside the student's worker and beside the solution's,
// and divides. Sent on the verdict channel (support/measure.h); run by hand it
// prints them:
//   part2_tests --gtest_also_run_disabled_tests --gtest_filter='Part2Leaderboard.*'
#include <cstdio>

#include "common.h"
#include "support/measure.h"

namespace pt::test::part2 {
namespace {

void measure(const std::string& name, double value) {
  std::printf("%s %.6g\n", name.c_str(), value);
  pt::grading::report_measure(name, value);
}

TEST(Part2Leaderboard, DISABLED_Measure) {
  WorkTotals all;
  auto scene = [&all](const std::string& name, const Part2Scene& s, const std::vector<Ray>& rays) {
    CountedBVH bvh(s.primitives(), 4);
    ASSERT_TRUE(bvh.structure().ok()) << name << ": " << bvh.structure().summary();
    for (const Ray& ray : rays) {
      Ray r = ray;
      Intersection isect;
      QueryWork w;
      bvh.closest(r, &isect, &w);
      all.add(w);
    }
    measure("sah_cost_" + name, sah_cost(bvh.tree()));
  };
  const Part2Scene mesh = make_mesh_scene(seed(401));
  scene("mesh", mesh, make_rays(mesh, 1000, seed(402)));
  const Part2Scene fibres = make_fibres(seed(403), 4096);
  scene("fibres", fibres, make_rays(fibres, 1000, seed(404)));
  if (HasFatalFailure()) return;
  measure("primitive_tests_per_ray", all.tests());
  measure("node_visits_per_ray", all.nodes());
}

}  // namespace
}  // namespace pt::test::part2
