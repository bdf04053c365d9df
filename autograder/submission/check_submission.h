#pragma once
// `pt-grade check-submission [TASKS]`, in the student release: what the
// grader will do with the task files, as far as a release without the hidden
// tests can tell: the stages of pipeline.h with the student's ending, and
// one step of its own. The steps it prints:
//
//  1. the files, taken by the grader's own intake;
//  2. the directives that read a file as data (file_directives.h), with the
//     grader's message;
//  3. the files the grader has its own copy of (skeleton/, tests/, the
//     build, prebuilt/): each compared with the SHA-256 the release shipped
//     (prebuilt/release.json), an edit or an addition named, since the
//     grader builds the task files without it;
//  4. each part built on its own, as the grader builds it (`partN_tests`, or
//     a worker beside the visible tests' verifier), pt-link-guard before the
//     link, then the compiler's list of the files it opened (what each file
//     includes), as the grader checks it;
//  5. the visible tests in the sandbox, scored as pt-grade run scores them,
//     and per part the hidden points this release cannot run.
//
// It prints the answer first (check_answer.h: per part, whose the file is,
// the visible score, what will differ at grading; READY or NOT READY); the
// failures of a part not started (every visible test "not implemented") are
// folded into one line.
//
// Exit status 0 when nothing above differs from what the grader will do
// (whatever the score), 1 when something does, 2 when it could not check.
//
// With format "github-classroom" the same check prints, on stdout, only its
// result for GitHub Classroom (classroom_result.h), and everything above on
// stderr: the workflow's log shows it, the step's output is the result.
#include <map>
#include <string>

#include "report/report.h"
#include "run/grade_part.h"
#include "sandbox/sandbox.h"

namespace pt::grade {

struct CheckOptions {
  std::string tasks;       // what would be submitted: a folder (tasks/) or a .zip
  std::string source_dir;  // the release's top folder (prebuilt/release.json)
  std::string build_dir;   // its build folder (cmake --preset default)
  GradeLimits limits;
  SandboxOptions sandbox;
  std::string format = "text";  // or "github-classroom"
};

int check_submission(const CheckOptions& options);

// The hidden tests the student release does not hold, per part, from its
// prebuilt/release.json (empty when there is none: an instructor's checkout,
// whose manifest lists the hidden tests themselves).
std::map<int, HiddenNotRun> hidden_not_run_in(const std::string& source_dir);

}  // namespace pt::grade
