#pragma once
// `pt-grade submission PATH`: grades a student's submission end to end
// (docs/architecture.md, "The course loop"): the stages of pipeline.h with
// the grader's ending.
//
//  - The grading kit's manifest (the trusted list of graded tests) is read
//    first; results.json is written at once, every part 0 of its maximum.
//  - The task files are taken from the folder or zip (submission_files.h),
//    and each is read for the directives that read a file as data
//    (file_directives.h: an #embed or an assembler's .incbin).
//  - Each part is built on its own in a fresh copy of the kit (no solution
//    source: the solution is prebuilt), confined: a compile error costs only
//    that part, its first errors go to the report; pt-link-guard checks each
//    link, and the compiler's list of the files it read is checked against
//    the task file, the framework's headers and what the kit's header probe
//    read (dependency_check.h).
//  - Each part is graded, hidden tests included, in the sandbox: the kit's
//    verifier beside the part's worker (boundary/README.md), results.json
//    rewritten as each part finishes; then the scene library is rendered
//    with the student's working parts (report.html).
//
// Time: each part's build and each part's grading have their own limit, and
// the whole submission a budget (autograder/README.md has the numbers).
#include <string>
#include <vector>

#include "run/grade_part.h"
#include "sandbox/sandbox.h"

namespace pt::grade {

struct SubmissionOptions {
  std::string path;       // the submission: a folder or a .zip
  std::string kit;        // the grading kit (tools/release/, target grader-kit)
  std::string json_path;  // Gradescope results.json
  std::string html_path;  // the report a person reads
  std::string prairielearn_path;  // PrairieLearn's results.json (prairielearn_report.h)
  std::string work;       // where the build tree goes (default: TMPDIR)
  bool keep_work = false;
  bool renders = true;
  bool count_extensions = false;  // extension tasks' points (P5T3) count
  bool leaderboard = false;       // results.json's Part 2 leaderboard (leaderboard.h)
  double build_seconds = 50;    // one part's compilation and link
  double render_seconds = 60;   // all renders of the report together
  double budget_seconds = 600;  // the whole submission
  GradeLimits limits;
  SandboxOptions sandbox;
};

// Returns 0 when the submission was graded (whatever its score, a rejected
// submission included), 2 when it could not be (no kit, a report that cannot
// be written).
int grade_submission(const SubmissionOptions& options);

}  // namespace pt::grade
