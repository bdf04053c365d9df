#pragma once
// The stages `pt-grade submission` and `pt-grade check-submission` share, in
// the grader's order, so that a student's check gives the grader's own
// verdicts and messages:
//
//  1. the files (intake/submission_files.h): anything but task files, in a
//     folder or a zip, rejects the whole submission before anything is built;
//  2. each file's directives that read a file as data
//     (intake/file_directives.h): a refusal costs that part only;
//  3. each part built on its own by a PartBuilder (the grading kit's confined
//     tree, or the student's own build), then the compiler's own list of the
//     files it read checked (compile/dependency_check.h: what a task file
//     includes): a refusal costs that part only;
//  4. each part built graded in the sandbox (run/grade_part.h).
//
// What differs is where a part is built and what becomes of each stage's
// result: each command is an Ending (submission.h: the grader's reports;
// check_submission.h: the student's answer).
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "intake/submission_files.h"
#include "report/redact.h"
#include "report/report.h"
#include "run/grade_part.h"
#include "run/manifest.h"

namespace pt::grade {

enum class Stage { Files, Directives, Build, Reads };

// A part built: its test binary, or its verifier (the kit's tests) and the
// worker built from the task file (boundary/README.md).
struct BuiltPart {
  std::string binary, worker;
};

// Where stage 3 builds a part.
class PartBuilder {
 public:
  virtual ~PartBuilder() = default;
  // "" with *built filled in, or why the part scores 0 (the compiler's
  // errors, the time limit), in the words of the report.
  virtual std::string build(const TaskFile& file, BuiltPart* built) = 0;
  // The files the compiler read for the part's task file that it may not
  // read (compile/dependency_check.h).
  virtual std::vector<std::string> unexpected_reads(const TaskFile& file) = 0;
};

// What a command makes of each stage as it ends, for one file.
class Ending {
 public:
  virtual ~Ending() = default;
  virtual void refused(const TaskFile& file, Stage stage, const std::string& why) = 0;
  virtual void accepted(const TaskFile&) {}  // stage 2 passed
  virtual void built(const TaskFile&, double /*seconds*/) {}
};

class Pipeline {
 public:
  // `expected`: each part's task file name; `graded`: the parts that have
  // graded tests (a file of another part is refused at stage 1).
  Pipeline(std::map<int, std::string> expected, std::set<int> graded, Ending& ending);

  // 1. False when the submission is rejected whole: submission().problems.
  bool take_files(const std::string& path);
  // 2.
  void check_directives();
  // 3.
  void build(PartBuilder& builder);
  // 4. Every part of `manifest` into report.parts, in order: graded where it
  // was built (`after_each` then called), else 0 with why_not_graded.
  void grade(const Manifest& manifest, const GradeLimits& limits, Sandbox& sandbox, const Redactor& redactor,
             const ImageFolders* images, Report& report, const std::function<void()>& after_each = {}) const;

  const Submission& submission() const { return submission_; }
  const std::vector<const TaskFile*>& buildable() const { return buildable_; }
  const std::map<int, BuiltPart>& built() const { return built_; }
  const std::map<int, std::string>& expected() const { return expected_; }
  // Stage 1's refusal of the whole submission, in the report's words.
  std::string rejection() const;
  // Why a part was not built: not submitted, or a stage's refusal ("" when neither).
  std::string why_not_graded(int part) const;

 private:
  std::map<int, std::string> expected_;
  std::set<int> graded_;
  Ending& ending_;
  Submission submission_;
  std::vector<const TaskFile*> buildable_;
  std::map<int, BuiltPart> built_;
  std::map<int, std::string> refused_;  // part -> why, from stages 2 and 3

  void refuse(const TaskFile& file, Stage stage, const std::string& why);
};

// What a failed build printed that a student needs: the compiler's errors
// first, paths relative to tree_dir, ninja's progress left out, 40 lines at most.
std::string compiler_errors(const std::string& output, const std::string& tree_dir);

}  // namespace pt::grade
