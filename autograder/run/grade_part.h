#pragma once
// Grading one part's test binary against the manifest's list of its tests.
//
// The binary runs in the sandbox with a verdict channel and a GoogleTest
// filter naming the tests that have no verdict yet. A test that starts and
// does not end within the per-test limit, or takes the process down, is
// charged with that and only that; the binary then starts again on the tests
// left, those of a task that has hung last. A part's runs share one time
// budget, and the tests it does not reach score nothing, with the reason. Only the manifest says which tests exist
// and what they are worth: a test without a verdict fails, and a binary that
// reports nothing scores 0 of the part's full maximum.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "process/exit_status.h"
#include "report/redact.h"
#include "run/manifest.h"
#include "run/test_images.h"
#include "sandbox/sandbox.h"

namespace pt::grade {

struct GradeLimits {
  double test_seconds = 20;   // one test: from its start to its end (also start-up and between tests)
  double part_seconds = 100;  // every run of one part's binary together
  Clock::time_point deadline = Clock::time_point::max();  // the submission's budget
  bool stop_at_first_failure = false;  // check-mutant needs one failing test, not all
  // With stop_at_first_failure: each test's seconds in an earlier run (of the
  // reference). The cheapest tests then run first, in runs by tier, so a
  // mutant that a cheap test catches never waits for the statistical ones.
  // The verdict is the same in any order; only the time to reach it changes.
  std::map<std::string, double> cheap_first;
};


struct TestResult {
  enum class Status { Passed, Failed, Skipped, Crashed, TimedOut, NoVerdict, NotRun };  // status_name()'s order
  ManifestTest test;
  Status status = Status::NotRun;
  std::string message;  // GoogleTest's failure text, or why there is no verdict
  std::string output;   // the last lines it printed, when it took the process down
  std::vector<TestImage> images;  // a failing image test's (test_images.h), checked
  double seconds = 0;

  bool passed() const { return status == Status::Passed; }
  bool died() const { return status == Status::Crashed || status == Status::TimedOut; }
  const char* status_name() const;  // "passed", "crashed", "not-run", ...
};

struct PartResult {
  int part = 0;
  std::string binary, log;
  bool graded = false;  // false: not graded (yet)
  std::vector<TestResult> tests;
  std::vector<std::string> notes;  // what an instructor should know about this binary
  int runs = 0;
  double seconds = 0;

  double earned() const;
  double possible() const;
};

// Where each run of a test binary may leave a failing image test's images
// (test_images.h): a fresh folder per run, made where the code under test
// could have planted nothing, and its removal once they are taken.
struct ImageFolders {
  std::function<std::string(std::string* error)> fresh;
  std::function<void(const std::string&)> discard;
  // The student's own check (check-submission) keeps the folders where its
  // messages name them, instead of taking the images into a report.
  bool kept = false;
};

// A part before it is graded: every test 0 of its points, with `why`.
PartResult pending_part(int part, const PartManifest& tests, const std::string& why);

// Grades `binary` as part `part`. The log (when not empty) receives each run's
// command line and the output kept from it, as it was; the messages and output
// in the result have the solution's lines removed (redact.h).
//
// With a `worker` (boundary/README.md), `binary` is the part's verifier: the
// tests with proxies of the part's task functions and no student code, and
// each of its runs has the worker beside it, in a sandbox run of its own,
// answering the proxies over a pipe each way. The verdicts are the
// verifier's; a worker that dies takes only the test it was answering.
//
// With `images`, each run may write a folder of its own, named to it with
// --pt_image_dir; the images of the tests that failed are taken into their
// results (test_images.h) and the folder removed.
PartResult grade_binary(int part, const std::string& binary, const PartManifest& tests, const GradeLimits& limits,
                        Sandbox& sandbox, const std::string& log_path, const Redactor& redactor = Redactor(),
                        const std::string& worker = "", const ImageFolders* images = nullptr);

// One run of a verifier (`request`, watched by `watch`) with its worker beside
// it, each in its own sandbox run (its own PID namespace where there are
// namespaces): the worker can neither see the verifier's memory nor write its
// verdict channel. Returns the verifier's run; the worker's is in worker_run.
RunOutcome run_with_worker(Sandbox& sandbox, RunRequest request, RunObserver& watch, const std::string& worker,
                           RunOutcome& worker_run);

}  // namespace pt::grade
