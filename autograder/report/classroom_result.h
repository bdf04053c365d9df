#pragma once
// `pt-grade check-submission --format github-classroom`: the check's result in
// the format GitHub Classroom's reporter action
// (classroom-resources/autograding-grading-reporter) reads from a step's
// output `result` (base64 of this JSON, tools/release/github-classroom/):
//
//   {"version": 1, "status": "pass"|"fail"|"error", "max_score": N,
//    "tests": [{"name", "status", "score", "message", "test_code", "filename",
//               "line_no", "duration"}]}
//
// The reporter shows each entry as a line (its message under a failed one)
// and GitHub Classroom records "Points X/Y": X the sum of the entries'
// scores, Y the sum of the runs' max_score. So:
//  - one entry per task, not per test: a task is what a student works on and
//    what a handout's section is about (twenty lines, not a hundred and
//    twenty); its score is the points of its visible tests that passed, its
//    message every failed test with its first lines;
//  - max_score is the visible points only: this run can award nothing else,
//    and a submission with every visible test passing reads Y/Y, as
//    check-submission's own table says;
//  - each part's hidden tests are one entry, status "error" (not run), score
//    0, their count and points named; they are outside max_score;
//  - one entry for the check's verdict (READY or what will differ), score 0;
//  - status "pass" when every counted visible test passed and nothing differs
//    from what the grader will do, "fail" otherwise, "error" when the check
//    could not run (classroom_error).
// The JSON is ASCII and at most kMaxClassroomBytes: the reporter reads the
// result from an environment variable, and Linux refuses one longer than
// 128 KiB (base64 makes 4 bytes of 3).
#include <map>
#include <string>
#include <vector>

#include "report/handout_index.h"
#include "report/report.h"

namespace pt::grade {

inline constexpr size_t kMaxClassroomBytes = 60000;

struct ClassroomFile {
  std::string path;  // tasks/part2_bvh.cpp
  std::string text;  // as checked
};

// The result of a check that ran: `files` by part (a part without one was not
// submitted), `problems` what check-submission found will differ at grading.
std::string classroom_result(const Report& report, const std::map<int, ClassroomFile>& files,
                             const HandoutIndex& handouts, const std::vector<std::string>& problems);

// The result of a check that stopped before any test ran: one entry named
// `what`, with `why`; status "fail" when the files are at fault (rejected at
// intake), "error" when the check could not run. max_score is `visible_points`
// when known (0 otherwise).
std::string classroom_stopped(const std::string& status, const std::string& what, const std::string& why,
                              double visible_points);

}  // namespace pt::grade
