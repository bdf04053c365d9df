#include "run/grade_part.h"

#include <poll.h>
#include <sched.h>
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

#include "boundary/one_cpu.h"
#include "boundary/verifier_exit_codes.h"
#include "process/launcher.h"
#include "report/report_text.h"
#include "run/run_outcome.h"
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

RunOutcome not_run(const std::string& why) {
  RunOutcome r;
  r.exit.how = Exit::How::NotStarted;
  r.exit.error = why;
  return r;
}

// The worker's run ends a second after its verifier's (the grader closes the
// write end of `verifier_done`), or sooner, by itself: a worker that has
// already died is seen dead, not stopped, and one still running reads the end
// of its link and leaves.
class WorkerWatch : public RunObserver {
 public:
  explicit WorkerWatch(int verifier_done) : verifier_done_(verifier_done) {}
  void on_channel(std::string_view) override {}
  Deadline deadline() const override {
    if (ends_ == Clock::time_point::max()) {
      pollfd p{verifier_done_, POLLIN, 0};
      if (::poll(&p, 1, 0) > 0) ends_ = Clock::now() + std::chrono::seconds(1);
    }
    return {std::min(ends_, Clock::now() + std::chrono::hours(1)), 0};
  }

 private:
  int verifier_done_;
  mutable Clock::time_point ends_ = Clock::time_point::max();
};

}  // namespace

// The worker's run is driven by a helper process, not a thread: the sandbox
// clones its processes with a raw clone(), which in a process with a second
// thread could copy a lock that thread holds (malloc's) and hang the copy.
RunOutcome run_with_worker(Sandbox& sandbox, RunRequest request, RunObserver& watch, const std::string& worker,
                           RunOutcome& worker_run) {
  Pipe to_worker, from_worker, done, outcome;
  for (Pipe* p : {&to_worker, &from_worker, &done, &outcome})
    if (!p->open()) return not_run(std::string("pipe: ") + std::strerror(errno));
  // Both runs inherit the CPU at their clone: the helper's for the worker,
  // this thread's (restored after the run) for the verifier.
  cpu_set_t before;
  const bool restore = ::sched_getaffinity(0, sizeof before, &before) == 0;
  const std::optional<cpu_set_t> cpu = boundary::one_cpu();
  LaunchOptions launch;
  launch.parent_death_signal = SIGKILL;
  launch.child_ends = {to_worker.read.get(), from_worker.write.get(), done.read.get(), outcome.write.get()};
  Child helper(launch, [&] {
    if (cpu) ::sched_setaffinity(0, sizeof *cpu, &*cpu);
    for (Fd* fd : {&to_worker.write, &from_worker.read, &done.write, &outcome.read}) fd->reset();
    RunRequest w{worker, {}, "", ""};
    w.link_read = to_worker.read.release();
    w.link_write = from_worker.write.release();
    WorkerWatch worker_watch(done.read.get());
    write_outcome(outcome.write.get(), sandbox.run(w, worker_watch));
    ::_exit(0);
  });
  for (Fd* fd : {&to_worker.read, &from_worker.write, &done.read, &outcome.write}) fd->release();  // closed by the launch
  if (!helper.started()) return not_run(std::string("fork: ") + std::strerror(helper.start_error()));
  request.args.push_back("--pt_worker_fds=5,6");
  request.link_read = from_worker.read.release();
  request.link_write = to_worker.write.release();
  if (cpu) ::sched_setaffinity(0, sizeof *cpu, &*cpu);
  RunOutcome run = sandbox.run(request, watch);
  if (cpu && restore) ::sched_setaffinity(0, sizeof before, &before);
  done.write.reset();
  worker_run = read_outcome(outcome.read.get());
  helper.wait();
  return run;
}

const char* TestResult::status_name() const {
  switch (status) {
    case Status::Passed:
      return "passed";
    case Status::Failed:
      return "failed";
    case Status::Skipped:
      return "skipped";
    case Status::Crashed:
      return "crashed";
    case Status::TimedOut:
      return "timed-out";
    case Status::NoVerdict:
      return "no-verdict";
    case Status::NotRun:
      break;
  }
  return "not-run";
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

}  // namespace

PartResult grade_binary(int part, const std::string& binary, const PartManifest& tests, const GradeLimits& limits,
                        Sandbox& sandbox, const std::string& log_path, const Redactor& redactor,
                        const std::string& worker, const ImageFolders* images) {
  PartResult res = pending_part(part, tests, "no verdict");
  res.binary = binary;
  res.log = log_path;
  res.graded = true;
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < res.tests.size(); ++i) index[res.tests[i].test.name] = i;
  std::ofstream log;
  if (!log_path.empty()) log.open(log_path, std::ios::trunc);

  const auto start = Clock::now();
  const auto part_budget_end =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.part_seconds));
  const bool submission_first = limits.deadline < part_budget_end;
  const auto part_end = std::min(part_budget_end, limits.deadline);
  size_t ignored = 0, unknown = 0, timed_out = 0, crashed = 0;
  std::set<std::string> hung_tasks;
  int threads_at_main = 0;
  uint64_t output_bytes = 0;
  size_t tests_with_images = 0, images_beyond_bound = 0;
  std::string image_folder_error;
  auto unresolved = [&] {
    std::vector<TestResult*> left;
    for (auto& t : res.tests)
      if (t.status == TestResult::Status::NotRun) left.push_back(&t);
    return left;
  };
  auto charge_rest = [&](TestResult::Status status, const std::string& why) {
    for (TestResult* t : unresolved()) {
      t->status = status;
      t->message = why;
    }
  };

  for (std::vector<TestResult*> left = unresolved(); !left.empty(); left = unresolved()) {
    if (Clock::now() >= part_end) {
      charge_rest(TestResult::Status::NotRun,
                  submission_first ? "not run: the submission's time budget was used up"
                                   : "not run: the part's time budget of " + seconds_text(limits.part_seconds) +
                                         " was used up (by " + std::to_string(timed_out) + " test(s) that hung)");
      break;
    }
    // The tests of a task that has hung wait until every other test has run:
    // the budget they may use up is then only theirs to lose.
    std::vector<TestResult*> next;
    for (TestResult* t : left)
      if (!hung_tasks.count(t->test.task)) next.push_back(t);
    if (next.empty()) next = left;
    if (limits.stop_at_first_failure) next = cheapest_tier(next, limits.cheap_first);
    std::string filter = "--gtest_filter=";
    for (const TestResult* t : next) filter += t->test.name + (t == next.back() ? "" : ":");
    // The test main's own limit (support/test_main.cpp) prints the hung
    // test's task and stack just before this one ends the run.
    char timeout_flag[64];
    std::snprintf(timeout_flag, sizeof timeout_flag, "--pt_test_timeout=%g", limits.test_seconds);
    RunRequest request{binary, {kChannelFlag, filter, "--gtest_color=no", timeout_flag}, make_key(), ""};
    if (limits.stop_at_first_failure) request.args.push_back("--gtest_fail_fast");
    // Removed at the end of this run's turn, however it ends.
    struct ImageFolder {
      const ImageFolders* folders;
      std::string path;
      ~ImageFolder() {
        if (!path.empty()) folders->discard(path);
      }
    } image_folder{images, images ? images->fresh(&image_folder_error) : ""};
    if (!image_folder.path.empty()) {
      request.output_dir = image_folder.path;
      request.args.push_back(kImageDirFlag + image_folder.path);
    }
    RunWatch watch(request.key, limits, part_end, submission_first);
    RunOutcome worker_run;
    const RunOutcome run =
        worker.empty() ? sandbox.run(request, watch) : run_with_worker(sandbox, request, watch, worker, worker_run);
    const bool worker_exit = !worker.empty() && run.exit.how == Exit::How::Exited;
    const bool worker_lost = worker_exit && run.exit.code == boundary::kWorkerLost;
    const bool worker_never_started = worker_exit && run.exit.code == boundary::kWorkerNeverStarted;
    const bool worker_broke_link = worker_exit && run.exit.code == boundary::kWorkerBrokeLink;
    ++res.runs;
    output_bytes += run.output_bytes;
    if (log) {
      log << "===== pt-grade: run " << res.runs << ": " << binary;
      for (const auto& a : request.args) log << " " << (a.size() > 200 ? a.substr(0, 200) + "..." : a);
      log << "\n" << run.output << "\n===== pt-grade: run " << res.runs << " " << run.exit.describe() << "\n";
      if (!worker.empty())
        log << "===== pt-grade: its worker " << worker << "\n"
            << worker_run.output << "\n===== pt-grade: the worker " << worker_run.exit.describe() << "\n";
      log << std::flush;
    }

    const VerdictStream& s = watch.stream();
    bool hidden_ran = false;  // in this run, before the test that died
    ignored += s.ignored();
    threads_at_main = std::max(threads_at_main, s.threads_at_main());
    size_t resolved = 0;
    for (const Verdict& v : s.verdicts()) {
      auto it = index.find(v.test);
      if (it == index.end()) {
        ++unknown;
        continue;
      }
      TestResult& t = res.tests[it->second];
      if (t.status != TestResult::Status::NotRun) continue;
      t.status = v.passed ? TestResult::Status::Passed
                 : v.skipped ? TestResult::Status::Skipped
                             : TestResult::Status::Failed;
      t.message = v.message;
      if (t.status == TestResult::Status::Skipped) t.message = "skipped (a skipped test earns no points)";
      if (t.status == TestResult::Status::Failed && t.message.empty()) t.message = "failed without a message";
      // Every process of the run is dead: nothing changes the folder now.
      if (t.status == TestResult::Status::Failed && !image_folder.path.empty() && !images->kept) {
        std::string refused;
        if (tests_with_images < kMaxImageTestsPerPart)
          t.images = take_test_images(image_folder.path, t.test.name, &refused);
        else if (t.message.find(image_folder.path + "/" + t.test.name + "/") != std::string::npos)
          ++images_beyond_bound;
        tests_with_images += !t.images.empty() || !refused.empty();
        if (!refused.empty())
          res.notes.push_back("images of the failing " + (t.test.hidden ? std::string("hidden test") : t.test.name) +
                              " refused:\n" + capped(refused, 2048));
        point_at_report(t.message, image_folder.path, t.test.name, !t.images.empty());
      }
      t.seconds = v.seconds;
      hidden_ran = hidden_ran || t.test.hidden;
      ++resolved;
    }
    if (worker_never_started) {
      const std::string why = "the worker running the task's code " + worker_run.exit.describe() +
                              " before its main started";
      for (TestResult* t : unresolved()) {
        t->status = TestResult::Status::NoVerdict;
        t->message = "no verdict: " + why;
        t->output = last_lines(worker_run.output);
      }
      res.notes.push_back(why + " (a static initializer?): every test of the part is charged with it");
      break;
    }
    if (auto it = index.find(s.running()); it != index.end() && res.tests[it->second].status == TestResult::Status::NotRun) {
      TestResult& t = res.tests[it->second];
      const bool hung = run.exit.how == Exit::How::TimedOut;
      t.status = hung ? TestResult::Status::TimedOut : TestResult::Status::Crashed;
      t.message = worker_broke_link ? "the worker running the task's code broke the link to the tests (it wrote what "
                                      "no honest worker writes) during this test"
                  : worker_lost ? "the worker running the task's code " + worker_run.exit.describe() + " during this test"
                  : run.exit.how == Exit::How::Exited ? run.exit.describe() + " during this test"
                                                      : why_died(run.exit, watch, limits);
      // The worker's output is the whole run's, hidden tests' calls included:
      // shown only when no hidden test ran before this one in the run.
      if (worker_lost || worker_broke_link)
        t.output = hidden_ran ? "(the worker's output is not shown: hidden tests ran in the same process before this "
                                "test)"
                              : last_lines(worker_run.output);
      else
        t.output = own_output(run.output, t.test.name);
      (hung ? timed_out : crashed) += 1;
      if (hung) hung_tasks.insert(t.test.task);
      ++resolved;
    }

    bool failed = false;
    for (const auto& t : res.tests)
      failed = failed || t.died() || t.status == TestResult::Status::Failed;
    if (limits.stop_at_first_failure && failed) {
      charge_rest(TestResult::Status::NotRun, "not run: grading stopped at the first failing test");
      break;
    }
    if (!s.hello()) {
      charge_rest(TestResult::Status::NoVerdict, "no verdict: the binary " + why_died(run.exit, watch, limits) +
                                                     " before its test main started");
      res.notes.push_back("the binary reported nothing: it " + run.exit.describe() +
                          " before its test main started (a static initializer?)");
      break;
    }
    if (resolved == 0) {
      charge_rest(TestResult::Status::NoVerdict,
                  "no verdict: the binary " + why_died(run.exit, watch, limits) + " without running this test");
      break;
    }
    if (s.done() && next.size() == left.size() && !unresolved().empty()) {
      charge_rest(TestResult::Status::NoVerdict,
                  "no verdict: the binary finished without running this test (is the manifest from another build?)");
      break;
    }
  }
  res.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  size_t redacted = 0;
  const std::vector<std::string> folders{std::filesystem::path(binary).parent_path().string(),
                                         worker.empty() ? "" : std::filesystem::path(worker).parent_path().string()};
  for (auto& t : res.tests) {
    redacted += redactor.redact(t.message) + redactor.redact(t.output);
    hide_folders(t.message, folders);
    hide_folders(t.output, folders);
  }
  if (redacted > 0)
    res.notes.push_back(std::to_string(redacted) +
                        " line(s) of the solution were removed from the tests' messages: the submission printed "
                        "solution text (read its task file)");

  if (res.runs > 1)
    res.notes.push_back("the binary was started " + std::to_string(res.runs) + " times: " + std::to_string(crashed) +
                        " test(s) crashed and " + std::to_string(timed_out) +
                        " hung; each was charged alone and the binary restarted on the tests left");
  if (threads_at_main > 1)
    res.notes.push_back(std::to_string(threads_at_main - 1) +
                        " thread(s) were already running when the test main started: only a static initializer in "
                        "the submission can start one (read its task file)");
  if (ignored > 0)
    res.notes.push_back(std::to_string(ignored) +
                        " line(s) on the verdict channel did not carry the run's key and were ignored: only code under "
                        "test writes such lines (read its task file)");
  if (unknown > 0)
    res.notes.push_back(std::to_string(unknown) +
                        " verdict(s) for tests the manifest does not list were ignored (an out-of-date manifest? "
                        "build the target graded_manifest)");
  if (images_beyond_bound > 0)
    res.notes.push_back("the images of " + std::to_string(images_beyond_bound) + " more failing test(s) were not kept: " +
                        std::to_string(kMaxImageTestsPerPart) + " tests' images per part at most");
  if (!image_folder_error.empty())
    res.notes.push_back("no folder for the image tests' images: " + image_folder_error);
  if (output_bytes > (1u << 20))
    res.notes.push_back("the binary printed " + std::to_string(output_bytes >> 20) +
                        " MiB; the log keeps only the head and the tail of each run");
  return res;
}

}  // namespace pt::grade
