#include "run/grade_part.h"

#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "boundary/verifier_exit_codes.h"
#include "process/launcher.h"
#include "report/report_text.h"
#include "run/verdicts.h"

namespace pt::grade {
namespace {

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

// The last lines a dying test printed, without GoogleTest's banners.
std::string last_lines(const std::string& output, size_t max_lines = 12) {
  std::deque<std::string> lines;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("[==", 0) == 0 || line.rfind("[--", 0) == 0 || line.rfind("[ RUN", 0) == 0 ||
        line.rfind("Note: Google Test filter", 0) == 0 || line.empty())
      continue;
    lines.push_back(line.size() > 240 ? line.substr(0, 240) + " ..." : line);
    if (lines.size() > max_lines) lines.pop_front();
  }
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : "\n") + l;
  return out;
}

// What the test `name` printed itself: the lines after GoogleTest's
// "[ RUN      ] name", never those of the tests before it in the run (a
// suite's hidden tests run before its visible ones, and their names and
// results are not a visible test's to show). Nothing when its start was not
// kept.
std::string own_output(const std::string& output, const std::string& name) {
  const std::string start = "[ RUN      ] " + name + "\n";
  const size_t at = output.rfind(start);
  if (at == std::string::npos) return "";
  return last_lines(output.substr(at + start.size()));
}

// `text` without the folders of the binaries graded (the grading kit's, the
// build's): a report names files, not where the grader keeps them.
void hide_folders(std::string& text, const std::vector<std::string>& folders) {
  for (const std::string& folder : folders) {
    if (folder.size() < 2) continue;
    const std::string prefix = folder + "/";
    for (size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
  }
}

// The verifier's message names the folder it wrote its images in
// (tests/support/image_test_files.cpp): a path of the grader's, gone by the
// time anyone reads the report.
void point_at_report(std::string& message, const std::string& folder, const std::string& test, bool taken) {
  const std::string written = folder + "/" + test + "/";
  const std::string instead = taken ? "the grader's HTML report, beside this message"
                                    : "a folder the grader did not keep (the part's notes say why)";
  for (size_t at; (at = message.find(written)) != std::string::npos;) message.replace(at, written.size(), instead);
}

// Follows one run's records and decides its deadline: the per-test limit,
// counted from the last record (so start-up and the gaps between tests are
// bounded too), or the part's budget, whichever comes first.
class RunWatch : public RunObserver {
 public:
  RunWatch(std::string key, const GradeLimits& limits, Clock::time_point part_end, bool part_end_is_submission)
      : stream_(std::move(key)), limits_(limits), part_end_(part_end), submission_(part_end_is_submission) {}

  void on_channel(std::string_view bytes) override {
    if (stream_.feed(bytes) > 0) last_record_ = Clock::now();
  }
  Deadline deadline() const override {
    const auto test_end = last_record_ + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(limits_.test_seconds));
    if (test_end <= part_end_) return {test_end, limits_.test_seconds};
    budget_hit_ = true;
    return {part_end_, limits_.part_seconds};
  }
  const VerdictStream& stream() const { return stream_; }
  // The deadline in force was the budget, not the per-test limit.
  bool budget_hit() const { return budget_hit_ && Clock::now() >= part_end_; }
  bool submission_budget() const { return submission_; }

 private:
  VerdictStream stream_;
  const GradeLimits& limits_;
  Clock::time_point part_end_;
  bool submission_;
  Clock::time_point last_record_ = Clock::now();
  mutable bool budget_hit_ = false;
};

std::string why_died(const Exit& e, const RunWatch& watch, const GradeLimits& limits) {
  if (e.how != Exit::How::TimedOut) return e.describe();
  if (!watch.budget_hit()) return "timed out after " + seconds_text(limits.test_seconds) + " (the limit per test)";
  return watch.submission_budget() ? "stopped: the submission's time budget ran out during this test"
                                   : "stopped: the part's time budget of " + seconds_text(limits.part_seconds) +
                                         " ran out during this test";
}

}  // namespace

const char* TestResult::status_name() const {
  static const char* const names[] = {"passed", "failed", "skipped", "crashed", "timed-out", "no-verdict", "not-run"};
  return names[static_cast<int>(status)];
}

double PartResult::earned() const {
  double sum = 0;
  for (const auto& t : tests) sum += t.passed() ? t.test.points : 0;
  return sum;
}

double PartResult::possible() const {
  double sum = 0;
  for (const auto& t : tests) sum += t.test.points;
  return sum;
}

PartResult pending_part(int part, const PartManifest& tests, const std::string& why) {
  PartResult r;
  r.part = part;
  // A long reason (an intake's refusals, a compiler's errors) once, in the
  // part's notes; each test says its first lines.
  const std::string each = summary(why, "the whole message is in the report's notes, under part " +
                                            std::to_string(part));
  if (each != why) r.notes.push_back(why);
  for (const auto& t : tests) {
    TestResult tr;
    tr.test = t;
    tr.message = each;
    r.tests.push_back(std::move(tr));
  }
  return r;
}

namespace {

// The tests of the cheapest tier that has any: under 0.25 s, under 2 s, the
// rest (a test with no time on record counts as cheap).
std::vector<TestResult*> cheapest_tier(const std::vector<TestResult*>& tests, const std::map<std::string, double>& seconds) {
  if (seconds.empty()) return tests;
  auto cost = [&](const TestResult* t) {
    const auto it = seconds.find(t->test.name);
    return it == seconds.end() ? 0.0 : it->second;
  };
  for (const double bound : {0.25, 2.0}) {
    std::vector<TestResult*> tier;
    for (TestResult* t : tests)
      if (cost(t) < bound) tier.push_back(t);
    if (!tier.empty()) return tier;
  }
  return tests;
}

// A folder for one run's images (ImageFolders), removed at the end of the
// run's turn however it ends.
struct ImageFolder {
  const ImageFolders* folders;
  std::string path;
  ImageFolder(const ImageFolders* f, std::string* error) : folders(f), path(f ? f->fresh(error) : "") {}
  ~ImageFolder() {
    if (!path.empty()) folders->discard(path);
  }
  ImageFolder(const ImageFolder&) = delete;
  ImageFolder& operator=(const ImageFolder&) = delete;
};

// How one run of a binary (and its worker) ended, as the grader saw it.
struct RunEnd {
  RunOutcome run, worker_run;
  bool worker_lost = false, worker_never_started = false, worker_broke_link = false;
};

// One binary's grading in progress. Its four jobs, once per run: choose the
// tests of the next run, run them, take the verdicts and charge a test that
// died, and decide whether to go on; then the notes for the instructor.
class PartGrading {
 public:
  PartGrading(int part, const std::string& binary, const PartManifest& tests, const GradeLimits& limits,
              const std::string& log_path, const std::string& worker, const ImageFolders* images)
      : res_(pending_part(part, tests, "no verdict")), limits_(limits), worker_(worker), images_(images),
        start_(Clock::now()) {
    res_.binary = binary;
    res_.log = log_path;
    res_.graded = true;
    for (size_t i = 0; i < res_.tests.size(); ++i) index_[res_.tests[i].test.name] = i;
    if (!log_path.empty()) log_.open(log_path, std::ios::trunc);
    const auto budget_end =
        start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.part_seconds));
    submission_first_ = limits.deadline < budget_end;
    part_end_ = std::min(budget_end, limits.deadline);
  }

  // Runs the binary until every test has its result or a reason it has none.
  void run_all(Sandbox& sandbox) {
    for (std::vector<TestResult*> left = unresolved(); !left.empty(); left = unresolved()) {
      if (Clock::now() >= part_end_) {
        charge_rest(TestResult::Status::NotRun,
                    submission_first_ ? "not run: the submission's time budget was used up"
                                      : "not run: the part's time budget of " + seconds_text(limits_.part_seconds) +
                                            " was used up (by " + std::to_string(timed_out_) + " test(s) that hung)");
        return;
      }
      const std::vector<TestResult*> next = next_tests(left);
      RunRequest request = request_for(next);
      ImageFolder folder(images_, &image_folder_error_);
      if (!folder.path.empty()) {
        request.output_dir = folder.path;
        request.args.push_back(kImageDirFlag + folder.path);
      }
      RunWatch watch(request.key, limits_, part_end_, submission_first_);
      const RunEnd end = run_once(sandbox, request, watch);
      if (!go_on(end, watch, folder.path, next.size() == left.size())) return;
    }
  }

  // The part's result: messages redacted and without the grader's folders,
  // and the notes an instructor should read.
  PartResult finish(const Redactor& redactor) {
    res_.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    size_t redacted = 0;
    const std::vector<std::string> folders{
        std::filesystem::path(res_.binary).parent_path().string(),
        worker_.empty() ? "" : std::filesystem::path(worker_).parent_path().string()};
    for (auto& t : res_.tests) {
      redacted += redactor.redact(t.message) + redactor.redact(t.output);
      hide_folders(t.message, folders);
      hide_folders(t.output, folders);
    }
    add_notes(redacted);
    return std::move(res_);
  }

 private:
  std::vector<TestResult*> unresolved() {
    std::vector<TestResult*> left;
    for (auto& t : res_.tests)
      if (t.status == TestResult::Status::NotRun) left.push_back(&t);
    return left;
  }

  void charge_rest(TestResult::Status status, const std::string& why, const std::string& output = "") {
    for (TestResult* t : unresolved()) {
      t->status = status;
      t->message = why;
      t->output = output;
    }
  }

  // The tests of a task that has hung wait until every other test has run:
  // the budget they may use up is then only theirs to lose.
  std::vector<TestResult*> next_tests(const std::vector<TestResult*>& left) const {
    std::vector<TestResult*> next;
    for (TestResult* t : left)
      if (!hung_tasks_.count(t->test.task)) next.push_back(t);
    if (next.empty()) next = left;
    if (limits_.stop_at_first_failure) next = cheapest_tier(next, limits_.cheap_first);
    return next;
  }

  RunRequest request_for(const std::vector<TestResult*>& tests) const {
    std::string filter = "--gtest_filter=";
    for (const TestResult* t : tests) filter += t->test.name + (t == tests.back() ? "" : ":");
    // The test main's own limit (support/test_main.cpp) prints the hung
    // test's task and stack just before this one ends the run.
    char timeout_flag[64];
    std::snprintf(timeout_flag, sizeof timeout_flag, "--pt_test_timeout=%g", limits_.test_seconds);
    RunRequest request{res_.binary, {kChannelFlag, filter, "--gtest_color=no", timeout_flag}, make_key(), ""};
    if (limits_.stop_at_first_failure) request.args.push_back("--gtest_fail_fast");
    return request;
  }

  RunEnd run_once(Sandbox& sandbox, const RunRequest& request, RunWatch& watch) {
    RunEnd e;
    e.run = worker_.empty() ? sandbox.run(request, watch)
                            : run_with_worker(sandbox, request, watch, worker_, e.worker_run);
    const bool worker_exit = !worker_.empty() && e.run.exit.how == Exit::How::Exited;
    e.worker_lost = worker_exit && e.run.exit.code == boundary::kWorkerLost;
    e.worker_never_started = worker_exit && e.run.exit.code == boundary::kWorkerNeverStarted;
    e.worker_broke_link = worker_exit && e.run.exit.code == boundary::kWorkerBrokeLink;
    ++res_.runs;
    output_bytes_ += e.run.output_bytes;
    if (log_) {
      log_ << "===== pt-grade: run " << res_.runs << ": " << res_.binary;
      for (const auto& a : request.args) log_ << " " << (a.size() > 200 ? a.substr(0, 200) + "..." : a);
      log_ << "\n" << e.run.output << "\n===== pt-grade: run " << res_.runs << " " << e.run.exit.describe() << "\n";
      if (!worker_.empty())
        log_ << "===== pt-grade: its worker " << worker_ << "\n"
             << e.worker_run.output << "\n===== pt-grade: the worker " << e.worker_run.exit.describe() << "\n";
      log_ << std::flush;
    }
    return e;
  }

  // The run's verdicts, each for a test still without one; with a failing
  // test's images taken from the run's folder. Returns how many it resolved;
  // *hidden_ran: a hidden test among them.
  size_t take_verdicts(const VerdictStream& s, const std::string& image_folder, bool* hidden_ran) {
    size_t resolved = 0;
    for (const Verdict& v : s.verdicts()) {
      auto it = index_.find(v.test);
      if (it == index_.end()) {
        ++unknown_;
        continue;
      }
      TestResult& t = res_.tests[it->second];
      if (t.status != TestResult::Status::NotRun) continue;
      t.status = v.passed ? TestResult::Status::Passed
                 : v.skipped ? TestResult::Status::Skipped
                             : TestResult::Status::Failed;
      t.message = v.message;
      if (t.status == TestResult::Status::Skipped) t.message = "skipped (a skipped test earns no points)";
      if (t.status == TestResult::Status::Failed && t.message.empty()) t.message = "failed without a message";
      // Every process of the run is dead: nothing changes the folder now.
      if (t.status == TestResult::Status::Failed && !image_folder.empty() && !images_->kept)
        take_images(t, image_folder);
      t.seconds = v.seconds;
      *hidden_ran = *hidden_ran || t.test.hidden;
      ++resolved;
    }
    return resolved;
  }

  void take_images(TestResult& t, const std::string& folder) {
    std::string refused;
    if (tests_with_images_ < kMaxImageTestsPerPart)
      t.images = take_test_images(folder, t.test.name, &refused);
    else if (t.message.find(folder + "/" + t.test.name + "/") != std::string::npos)
      ++images_beyond_bound_;
    tests_with_images_ += !t.images.empty() || !refused.empty();
    if (!refused.empty())
      res_.notes.push_back("images of the failing " + (t.test.hidden ? std::string("hidden test") : t.test.name) +
                           " refused:\n" + capped(refused, 2048));
    point_at_report(t.message, folder, t.test.name, !t.images.empty());
  }

  // The test running when the run ended, charged with how it ended (a hang,
  // a crash, the worker's death); true when there was one.
  bool charge_running(const VerdictStream& s, const RunEnd& e, const RunWatch& watch, bool hidden_ran) {
    const auto it = index_.find(s.running());
    if (it == index_.end() || res_.tests[it->second].status != TestResult::Status::NotRun) return false;
    TestResult& t = res_.tests[it->second];
    const bool hung = e.run.exit.how == Exit::How::TimedOut;
    t.status = hung ? TestResult::Status::TimedOut : TestResult::Status::Crashed;
    t.message = e.worker_broke_link ? "the worker running the task's code broke the link to the tests (it wrote what "
                                      "no honest worker writes) during this test"
                : e.worker_lost ? "the worker running the task's code " + e.worker_run.exit.describe() +
                                      " during this test"
                : e.run.exit.how == Exit::How::Exited ? e.run.exit.describe() + " during this test"
                                                      : why_died(e.run.exit, watch, limits_);
    // The worker's output is the whole run's, hidden tests' calls included:
    // shown only when no hidden test ran before this one in the run.
    if (e.worker_lost || e.worker_broke_link)
      t.output = hidden_ran ? "(the worker's output is not shown: hidden tests ran in the same process before this "
                              "test)"
                            : last_lines(e.worker_run.output);
    else
      t.output = own_output(e.run.output, t.test.name);
    (hung ? timed_out_ : crashed_) += 1;
    if (hung) hung_tasks_.insert(t.test.task);
    return true;
  }

  // Takes what the run showed; false when the part is over (every test has
  // its result, or what is left can have none).
  bool go_on(const RunEnd& e, const RunWatch& watch, const std::string& image_folder, bool asked_for_all) {
    const VerdictStream& s = watch.stream();
    bool hidden_ran = false;  // in this run, before the test that died
    ignored_ += s.ignored();
    threads_at_main_ = std::max(threads_at_main_, s.threads_at_main());
    size_t resolved = take_verdicts(s, image_folder, &hidden_ran);
    if (e.worker_never_started) {
      const std::string why = "the worker running the task's code " + e.worker_run.exit.describe() +
                              " before its main started";
      charge_rest(TestResult::Status::NoVerdict, "no verdict: " + why, last_lines(e.worker_run.output));
      res_.notes.push_back(why + " (a static initializer?): every test of the part is charged with it");
      return false;
    }
    resolved += charge_running(s, e, watch, hidden_ran);
    bool failed = false;
    for (const auto& t : res_.tests) failed = failed || t.died() || t.status == TestResult::Status::Failed;
    if (limits_.stop_at_first_failure && failed) {
      charge_rest(TestResult::Status::NotRun, "not run: grading stopped at the first failing test");
      return false;
    }
    if (!s.hello()) {
      charge_rest(TestResult::Status::NoVerdict, "no verdict: the binary " + why_died(e.run.exit, watch, limits_) +
                                                     " before its test main started");
      res_.notes.push_back("the binary reported nothing: it " + e.run.exit.describe() +
                           " before its test main started (a static initializer?)");
      return false;
    }
    if (resolved == 0) {
      charge_rest(TestResult::Status::NoVerdict,
                  "no verdict: the binary " + why_died(e.run.exit, watch, limits_) + " without running this test");
      return false;
    }
    if (s.done() && asked_for_all && !unresolved().empty()) {
      charge_rest(TestResult::Status::NoVerdict,
                  "no verdict: the binary finished without running this test (is the manifest from another build?)");
      return false;
    }
    return true;
  }

  void add_notes(size_t redacted) {
    auto note = [this](const std::string& text) { res_.notes.push_back(text); };
    if (redacted > 0)
      note(std::to_string(redacted) +
           " line(s) of the solution were removed from the tests' messages: the submission printed solution text "
           "(read its task file)");
    if (res_.runs > 1)
      note("the binary was started " + std::to_string(res_.runs) + " times: " + std::to_string(crashed_) +
           " test(s) crashed and " + std::to_string(timed_out_) +
           " hung; each was charged alone and the binary restarted on the tests left");
    if (threads_at_main_ > 1)
      note(std::to_string(threads_at_main_ - 1) +
           " thread(s) were already running when the test main started: only a static initializer in the "
           "submission can start one (read its task file)");
    if (ignored_ > 0)
      note(std::to_string(ignored_) +
           " line(s) on the verdict channel did not carry the run's key and were ignored: only code under test "
           "writes such lines (read its task file)");
    if (unknown_ > 0)
      note(std::to_string(unknown_) +
           " verdict(s) for tests the manifest does not list were ignored (an out-of-date manifest? build the "
           "target graded_manifest)");
    if (images_beyond_bound_ > 0)
      note("the images of " + std::to_string(images_beyond_bound_) + " more failing test(s) were not kept: " +
           std::to_string(kMaxImageTestsPerPart) + " tests' images per part at most");
    if (!image_folder_error_.empty()) note("no folder for the image tests' images: " + image_folder_error_);
    if (output_bytes_ > (1u << 20))
      note("the binary printed " + std::to_string(output_bytes_ >> 20) +
           " MiB; the log keeps only the head and the tail of each run");
  }

  PartResult res_;
  const GradeLimits& limits_;
  const std::string worker_;
  const ImageFolders* images_;
  const Clock::time_point start_;
  Clock::time_point part_end_;
  bool submission_first_ = false;
  std::map<std::string, size_t> index_;
  std::ofstream log_;
  std::set<std::string> hung_tasks_;
  size_t ignored_ = 0, unknown_ = 0, timed_out_ = 0, crashed_ = 0;
  int threads_at_main_ = 0;
  uint64_t output_bytes_ = 0;
  size_t tests_with_images_ = 0, images_beyond_bound_ = 0;
  std::string image_folder_error_;
};

}  // namespace

PartResult grade_binary(int part, const std::string& binary, const PartManifest& tests, const GradeLimits& limits,
                        Sandbox& sandbox, const std::string& log_path, const Redactor& redactor,
                        const std::string& worker, const ImageFolders* images) {
  PartGrading grading(part, binary, tests, limits, log_path, worker, images);
  grading.run_all(sandbox);
  return grading.finish(redactor);
}

}  // namespace pt::grade
