#pragma once
// The Part 2 leaderboard in Gradescope's results.json ("leaderboard": name,
// value, order), when the instructor turns it on (`pt-grade submission
// --leaderboard`, a line of autograder/gradescope/grading.args). It measures
// work, never time: tests/part2/test_bvh_leaderboard.cpp builds the student's
// tree on two fixed scenes and traces 1,000 rays in each, counted by the
// verifier as the graded quality tests count them (autograder/README.md,
// "What the verifier counts"), and sends the numbers on the run's keyed
// verdict channel, so that nothing the student's worker prints can forge
// them. The same test beside the solution's worker (the kit's
// verifiers/part2_worker_reference) gives the yardstick:
//
//   "SAH cost / solution's"    geometric mean over the scenes of the tree's
//                              SAH cost over the solution's (1 for the
//                              solution itself), smaller is better;
//   "Primitive tests per ray"  the student's traversal on the student's tree;
//   "Node visits per ray"      the same (nodes on the paths to the leaves
//                              entered, support/bvh_checks.h).
//
// No name: Gradescope shows a leaderboard under the names students choose
// there themselves.
#include <map>
#include <string>

#include "report/report.h"
#include "sandbox/sandbox.h"

namespace pt::grade {

// The measurements of one run of the leaderboard test in `verifier` beside
// `worker`, within `seconds`: empty, with *why, when it sent none (a tree
// that does not build, a worker that died).
std::map<std::string, double> leaderboard_measures(Sandbox& sandbox, const std::string& verifier,
                                                   const std::string& worker, double seconds, std::string* why);

// The entries from the student's measurements and the solution's; empty, with
// *why, when either lacks one.
std::vector<LeaderboardEntry> leaderboard_entries(const std::map<std::string, double>& student,
                                                  const std::map<std::string, double>& solution, std::string* why);

// For `pt-grade submission --leaderboard`: report.leaderboard from part 2's
// verifier beside the submission's worker and beside the kit's solution
// worker, within what is left before `deadline` (60 s at most); a note in the
// report instead when part 2 was not graded across the boundary (either is
// "") or its tree gave no measurements.
void add_leaderboard(Report& report, const std::string& kit, const std::string& verifier, const std::string& worker,
                     Sandbox& sandbox, Clock::time_point deadline);

}  // namespace pt::grade
