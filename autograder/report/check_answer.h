#pragma once
// The answer `pt-grade check-submission` leads with: per part, whose the
// task file is, its visible score and what will differ at grading; then
// READY or NOT READY. The steps' details follow it (check_submission.cpp).
#include <map>
#include <string>
#include <vector>

#include "report/report.h"
#include "run/grade_part.h"

namespace pt::grade {

// A task file's state from its text, by the rule `pathtracer` uses for
// PT_REFERENCE_PARTS=auto: "yours" once no task throws NotImplemented
// (comments aside), else "started: P3T4, P3T5 still throw NotImplemented".
std::string task_file_state(const std::string& text);

// Every visible test of the part failed, each with a task's "not implemented"
// message: the part is not started, and its failures say nothing new.
bool untouched(const PartResult& part);

struct PartAnswer {
  int part = 0;
  std::string state;     // "yours", "not started", "started: ...", "not submitted", "does not build", ...
  double earned = 0, possible = 0;
  HiddenNotRun hidden;   // what this release cannot run
  std::string differs;   // what the grader will do otherwise ("" when nothing)
};

// The answer's table and verdict, on stdout.
// `as_grader`: false when this check ran the tests without the grader's
// sandbox (a build off Linux): READY then says how far it goes.
void print_answer(const std::vector<PartAnswer>& parts, const std::vector<std::string>& problems,
                  bool as_grader = true);

}  // namespace pt::grade
