// pt-grade: scores the graded GoogleTest binaries (docs/architecture.md, "How tests grade"),
// checks the stubs and the mutant gallery with the same machinery, and writes
// the manifest those rely on. How it keeps a hostile submission from writing
// its own grade: README.md beside this file.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "build_paths.h"
#include "process/command.h"
#include "report/redact.h"
#include "report/report.h"
#include "run/checks.h"
#include "run/grade_part.h"
#include "run/manifest.h"
#include "sandbox/sandbox.h"
#include "submission/check_submission.h"
#include "submission/submission.h"

namespace {

namespace fs = std::filesystem;
using namespace pt::grade;

struct Options {
  GradeLimits limits;
  double submission_seconds = 540;
  SandboxOptions sandbox;
  std::string manifest;
  bool count_extensions = false;
  std::map<int, std::string> workers;  // part -> its worker: the binary graded is that part's verifier
};

std::string worker_of(const Options& opt, int part) {
  const auto it = opt.workers.find(part);
  return it == opt.workers.end() ? "" : it->second;
}

// "N=FILE" arguments as a map.
std::map<int, std::string> numbered_files(const std::vector<std::string>& args, const char* option) {
  std::map<int, std::string> files;
  for (const auto& b : args) {
    const auto eq = b.find('=');
    const int n = eq == std::string::npos ? 0 : std::atoi(b.substr(0, eq).c_str());
    if (n < 1 || n > 99) throw std::runtime_error(std::string(option) + " expects N=FILE, got " + b);
    files[n] = b.substr(eq + 1);
  }
  return files;
}

// A trusted binary's own listing (`pt-grade manifest`), or, with no manifest,
// the listing of the binary under test, which a hostile one can fake.
PartManifest list_tests(int part, const std::string& binary, Sandbox& sandbox) {
  struct Wait : RunObserver {
    Clock::time_point end = Clock::now() + std::chrono::seconds(60);
    void on_channel(std::string_view) override {}
    Deadline deadline() const override { return {end, 60}; }
  } wait;
  const RunOutcome r = sandbox.run({binary, {"--pt_list_graded"}, "", ""}, wait);
  if (!r.exit.exited_ok())
    throw std::runtime_error(binary + " --pt_list_graded " + r.exit.describe() + ":\n" + r.output.substr(0, 2000));
  try {
    return parse_listing(part, r.output);
  } catch (const std::exception& e) {
    throw std::runtime_error(binary + " --pt_list_graded: " + e.what());
  }
}

// The manifest's tests of a part; without a manifest, what the binary says,
// with a note in the report that it was not a trusted list.
PartManifest tests_of(int part, const std::string& binary, const Manifest* manifest, Sandbox& sandbox,
                      std::vector<std::string>& notes) {
  if (manifest) {
    auto it = manifest->parts.find(part);
    if (it != manifest->parts.end()) return it->second;
    throw std::runtime_error("the manifest lists no part " + std::to_string(part));
  }
  notes.push_back("part " + std::to_string(part) +
                  ": no manifest: the tests and their points were read from the binary under test, which a hostile "
                  "submission can fake (build the target graded_manifest, or pass --manifest)");
  return list_tests(part, binary, sandbox);
}

std::unique_ptr<Manifest> load_manifest(const std::string& path, bool count_extensions) {
  if (path.empty()) return nullptr;
  auto manifest = std::make_unique<Manifest>(read_manifest(path));
  if (!count_extensions) leave_extensions_uncounted(*manifest);
  return manifest;
}

Report start_report(const Sandbox& sandbox) {
  Report r;
  r.sandbox_layers = sandbox.layers();
  r.sandbox_missing = sandbox.layers_missing();
  r.sandbox_ids = sandbox.layer_ids();
  for (const auto& m : sandbox.layers_missing()) r.notes.push_back("sandbox layer missing: " + m);
  return r;
}

int run(const std::string& build_dir, const std::vector<int>& numbers, const std::map<int, std::string>& binaries,
        Options opt, const std::string& json_path, bool show_hidden) {
  const auto start = Clock::now();
  opt.limits.deadline = start + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(opt.submission_seconds));
  if (opt.manifest.empty()) {
    const fs::path found = fs::path(build_dir) / "tests" / "graded_manifest.json";
    if (fs::is_regular_file(found)) opt.manifest = found.string();
  }
  // Read once, before any code under test runs, and never again.
  const auto manifest = load_manifest(opt.manifest, opt.count_extensions);
  const Redactor redactor(manifest ? manifest->solution_lines : std::set<uint64_t>());
  Sandbox sandbox(opt.sandbox);
  Report report = start_report(sandbox);
  report.hidden_not_run = hidden_not_run_in(build_paths::source_root());  // the student release's hidden tests
  auto save = [&] {
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (!json_path.empty()) write_results_json(json_path, report);
  };

  std::vector<std::string> paths;
  for (int n : numbers) {
    auto it = binaries.find(n);
    paths.push_back(it != binaries.end() ? it->second
                                         : (fs::path(build_dir) / "tests" / ("part" + std::to_string(n) + "_tests")).string());
  }
  // Every part is in the report, 0 of its maximum, before anything runs: an
  // outer timeout or a killed grader still leaves an honest partial report.
  std::vector<PartManifest> tests(numbers.size());
  for (size_t i = 0; i < numbers.size(); ++i) {
    if (manifest || fs::is_regular_file(paths[i])) tests[i] = tests_of(numbers[i], paths[i], manifest.get(), sandbox, report.notes);
    report.parts.push_back(pending_part(numbers[i], tests[i], "not graded yet: the grader stopped before this part"));
  }
  save();
  for (size_t i = 0; i < numbers.size(); ++i) {
    if (!fs::is_regular_file(paths[i])) {
      report.parts[i] = pending_part(numbers[i], tests[i], "not graded: " + paths[i] + " not found");
      report.notes.push_back("part " + std::to_string(numbers[i]) + ": " + paths[i] + " not found, not graded");
      continue;
    }
    report.parts[i] = grade_binary(numbers[i], paths[i], tests[i], opt.limits, sandbox, paths[i] + ".grade.log",
                                   redactor, worker_of(opt, numbers[i]));
    save();  // the run's processes are all dead by now: nothing of it outlives this write
  }
  report.complete = true;
  save();
  bool any = false;
  for (const auto& p : report.parts) any = any || p.graded;
  if (!any) {
    for (const auto& n : report.notes) std::fprintf(stderr, "pt-grade: %s\n", n.c_str());
    std::fprintf(stderr, "pt-grade: no test binaries found under %s/tests: build them first\n", build_dir.c_str());
    return 2;
  }
  print_report(report, show_hidden);
  return 0;
}

PartResult grade_one(int part, const std::string& binary, const Options& opt) {
  const auto manifest = load_manifest(opt.manifest, opt.count_extensions);
  Sandbox sandbox(opt.sandbox);
  std::vector<std::string> notes;
  const PartManifest tests = tests_of(part, binary, manifest.get(), sandbox, notes);
  PartResult r = grade_binary(part, binary, tests, opt.limits, sandbox, binary + ".grade.log",
                              Redactor(manifest ? manifest->solution_lines : std::set<uint64_t>()), worker_of(opt, part));
  r.notes.insert(r.notes.begin(), notes.begin(), notes.end());
  return r;
}

int write_manifest_from(const std::string& out, const std::vector<std::string>& listed,
                        const std::vector<std::string>& solution_files) {
  SandboxOptions plain;
  plain.confine = false;  // the all-reference binaries are the grader's own
  Sandbox sandbox(plain);
  Manifest m;
  std::map<int, std::string> sources;
  for (const auto& [part, binary] : numbered_files(listed, "manifest")) {
    m.parts[part] = list_tests(part, binary, sandbox);
    sources[part] = fs::path(binary).filename().string();
  }
  for (const auto& file : solution_files)
    for (uint64_t h : line_fingerprints(file)) m.solution_lines.insert(h);
  write_manifest(out, m, sources);
  return 0;
}

int print_sandbox(const SandboxOptions& options) {
  const Sandbox sandbox(options);
  const nlohmann::json j = {{"uid", ::geteuid()},
                            {"layers", sandbox.layers()},
                            {"missing", sandbox.layers_missing()},
                            {"ids", sandbox.layer_ids()}};
  std::cout << j.dump(2) << "\n";
  return 0;
}

// A GTEST_FILTER or GTEST_REPEAT left in the environment would silently change
// what gets graded (the sandbox passes no environment on; plain runs would).
void scrub_gtest_environment() {
  std::vector<std::string> names;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "GTEST_", 6) == 0) {
      const char* eq = std::strchr(*e, '=');
      names.emplace_back(*e, eq ? static_cast<size_t>(eq - *e) : std::strlen(*e));
    }
  for (const auto& n : names) ::unsetenv(n.c_str());
}

// A subcommand, and what it does once the command line is parsed.
struct Command {
  CLI::App* cmd;
  std::function<int()> action;
};

// The options the grading subcommands share, and how each adds them.
struct Common {
  Options opt;
  CLI::Validator seconds{[](std::string& text) -> std::string {
                           char* end = nullptr;
                           const double v = std::strtod(text.c_str(), &end);
                           return *end == '\0' && v > 0 && v <= 1e6
                                      ? ""
                                      : "expected a number of seconds in (0, 1e6], got " + text;
                         },
                         ""};

  void add_sandbox_choice(CLI::App* cmd) {
    cmd->add_option("--sandbox-user", opt.sandbox.user, "who runs the code under test when pt-grade is root")
        ->type_name("USER")
        ->capture_default_str();
    cmd->add_option("--sandbox-without", opt.sandbox.without, "leave out these layers, to test the fallbacks")
        ->delimiter(',')
        ->check(CLI::IsMember({"namespaces", "user", "landlock", "seccomp"}))
        ->type_name("LAYER,...");
    cmd->add_flag("--no-sandbox", [this](std::int64_t) { opt.sandbox.confine = false; },
                  "run the code under test with only its limits, session and subreaper (debugging only)");
  }

  void add_grading(CLI::App* cmd) {
    cmd->add_option("--manifest", opt.manifest, "the trusted list of graded tests (pt-grade manifest)")
        ->type_name("FILE")
        ->check(CLI::ExistingFile);
    cmd->add_option("--test-timeout", opt.limits.test_seconds, "time allowed to one test")
        ->check(seconds)
        ->type_name("SECONDS")
        ->capture_default_str();
    cmd->add_option("--part-budget,--timeout", opt.limits.part_seconds, "time allowed to all runs of one part")
        ->check(seconds)
        ->type_name("SECONDS")
        ->capture_default_str();
    cmd->add_option("--sandbox-read", opt.sandbox.readable, "a path the code under test may read (repeatable)")
        ->type_name("PATH");
    cmd->add_option("--sandbox-processes", opt.sandbox.limits.processes,
                    "processes and threads the code under test may have, where that can be counted")
        ->check(CLI::Range(8, 100000))
        ->type_name("N")
        ->capture_default_str();
    add_sandbox_choice(cmd);
  }
};

Command add_run(CLI::App& app, Common& c) {
  struct Args {
    std::string build_dir = "build", json_path;
    std::vector<int> parts{1, 2, 3, 4, 5};
    std::vector<std::string> binaries, workers;
    bool show_hidden = false;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("run", "grade DIR/tests/partN_tests of each part (the default)");
  cmd->add_option("--build-dir", a->build_dir, "build directory")->type_name("DIR")->capture_default_str();
  cmd->add_option("--parts", a->parts, "parts to grade")->delimiter(',')->type_name("N,...")->capture_default_str();
  cmd->add_option("--binary", a->binaries, "grade FILE as part N instead of DIR/tests/partN_tests")->type_name("N=FILE");
  cmd->add_option("--worker", a->workers,
                  "part N's task code runs in FILE, a worker; its binary is then the part's verifier "
                  "(autograder/boundary/README.md)")
      ->type_name("N=FILE");
  c.add_grading(cmd);
  cmd->add_flag("--count-extensions", c.opt.count_extensions,
                "count the points of extension tasks (P5T3); otherwise they are graded at 0 points");
  cmd->add_option("--budget", c.opt.submission_seconds, "time allowed to all parts together")
      ->check(c.seconds)
      ->type_name("SECONDS")
      ->capture_default_str();
  cmd->add_option("--json", a->json_path, "write a Gradescope results.json")->type_name("FILE");
  cmd->add_flag("--hidden", a->show_hidden, "show the names and failures of hidden tests too");
  return {cmd, [a, &c] {
    const std::map<int, std::string> binaries = numbered_files(a->binaries, "--binary");
    c.opt.workers = numbered_files(a->workers, "--worker");
    return run(a->build_dir, a->parts, binaries, c.opt, a->json_path, a->show_hidden);
  }};
}

// check-stubs and check-mutant: one part's binary, graded, then judged.
Command add_check(CLI::App& app, Common& c, const char* name, const char* what, const char* binary_is,
                  int (*judge)(const PartResult&), bool can_fail_fast) {
  struct Args {
    int part = 0;
    std::string binary, worker, cheap_first;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(name, what);
  cmd->add_option("--part", a->part, "the part the binary tests")->required()->check(CLI::Range(1, 99))->type_name("N");
  cmd->add_option("BINARY", a->binary, binary_is)->required()->check(CLI::ExistingFile);
  cmd->add_option("--worker", a->worker, "the part's worker: BINARY is then its verifier")->check(CLI::ExistingFile);
  c.add_grading(cmd);
  if (can_fail_fast) {
    cmd->add_flag("--fail-fast", c.opt.limits.stop_at_first_failure, "stop at the first failing test");
    cmd->add_option("--cheap-first", a->cheap_first,
                    "with --fail-fast: run the tests that took least time in this results.json first "
                    "(the reference's; a missing file changes nothing)")
        ->type_name("FILE");
  }
  return {cmd, [a, &c, judge] {
    if (!a->worker.empty()) c.opt.workers[a->part] = a->worker;
    if (!a->cheap_first.empty()) c.opt.limits.cheap_first = test_seconds_from_results(a->cheap_first);
    return judge(grade_one(a->part, a->binary, c.opt));
  }};
}

Command add_manifest(CLI::App& app) {
  struct Args {
    std::string out;
    std::vector<std::string> listed, solution_files;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("manifest", "write the manifest from trusted (all-reference) test binaries");
  cmd->add_option("--out", a->out, "the manifest to write")->required()->type_name("FILE");
  cmd->add_option("BINARIES", a->listed, "each part's all-reference test binary")->required()->type_name("N=FILE");
  cmd->add_option("--solution", a->solution_files, "files whose lines must never reach a report")
      ->type_name("FILE...")
      ->check(CLI::ExistingFile);
  return {cmd, [a] { return write_manifest_from(a->out, a->listed, a->solution_files); }};
}

Command add_submission(CLI::App& app, Common& c) {
  auto sub = std::make_shared<SubmissionOptions>();
  sub->kit = build_paths::default_kit();
  {
    // A kit's own copy of pt-grade (KIT/bin/pt-grade) grades with that kit.
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec && fs::is_regular_file(exe.parent_path().parent_path() / "manifest.json"))
      sub->kit = exe.parent_path().parent_path().string();
  }
  CLI::App* cmd = app.add_subcommand(
      "submission", "build and grade a submission (a folder or .zip of tasks/partN_*.cpp) in the grading kit");
  cmd->add_option("PATH", sub->path, "the submission: a folder or a .zip")->required();
  cmd->add_option("--kit", sub->kit, "the grading kit (target grader-kit)")->type_name("DIR")->capture_default_str();
  cmd->add_option("--json", sub->json_path, "write a Gradescope results.json")->type_name("FILE");
  cmd->add_option("--html", sub->html_path, "write the report a person reads")->type_name("FILE");
  cmd->add_option("--prairielearn", sub->prairielearn_path, "write PrairieLearn's results.json")->type_name("FILE");
  cmd->add_option("--work", sub->work, "folder for the build tree (default: TMPDIR)")->type_name("DIR");
  cmd->add_flag("--keep-work", sub->keep_work, "keep the build tree");
  cmd->add_flag("--no-renders", [sub](std::int64_t) { sub->renders = false; }, "no renders in the report");
  cmd->add_option("--render-seconds", sub->render_seconds, "time for the report's builds and renders together")
      ->check(CLI::Range(5.0, 3600.0));
  cmd->add_option("--build-timeout", sub->build_seconds, "time allowed to build one part")
      ->check(c.seconds)
      ->type_name("SECONDS")
      ->capture_default_str();
  cmd->add_option("--budget", sub->budget_seconds, "time allowed to the whole submission")
      ->check(c.seconds)
      ->type_name("SECONDS")
      ->capture_default_str();
  c.add_grading(cmd);
  cmd->add_flag("--count-extensions", sub->count_extensions,
                "count the points of extension tasks (P5T3); otherwise they are graded at 0 points");
  cmd->add_flag("--leaderboard", sub->leaderboard,
                "add Gradescope's leaderboard: Part 2's SAH cost against the solution's, primitive tests and node "
                "visits per ray (autograder/report/leaderboard.h)");
  return {cmd, [sub, &c] {
    sub->limits = c.opt.limits;
    sub->sandbox = c.opt.sandbox;
    return grade_submission(*sub);
  }};
}

Command add_check_submission(CLI::App& app, Common& c) {
  auto check = std::make_shared<CheckOptions>();
  check->source_dir = build_paths::source_root();
  check->build_dir = build_paths::binary_root();
  check->tasks = (fs::path(check->source_dir) / "tasks").string();
  CLI::App* cmd = app.add_subcommand(
      "check-submission",
      "in the student release: what the grader will do with your task files (intake, includes, edited framework "
      "files, each part built alone, the visible tests, the hidden points not run)");
  cmd->add_option("TASKS", check->tasks, "the folder or .zip you will submit")->capture_default_str();
  cmd->add_option("--build-dir", check->build_dir, "the release's build folder")->type_name("DIR")->capture_default_str();
  cmd->add_option("--format", check->format,
                  "github-classroom: only the result for GitHub Classroom's reporter on stdout (JSON), the rest on "
                  "stderr")
      ->check(CLI::IsMember({"text", "github-classroom"}))
      ->capture_default_str();
  c.add_grading(cmd);
  return {cmd, [check, &c] {
    check->limits = c.opt.limits;
    check->sandbox = c.opt.sandbox;
    return check_submission(*check);
  }};
}

Command add_sandbox(CLI::App& app, Common& c) {
  CLI::App* cmd = app.add_subcommand("sandbox", "print the sandbox layers this machine offers (JSON)");
  c.add_sandbox_choice(cmd);
  return {cmd, [&c] { return print_sandbox(c.opt.sandbox); }};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pt-grade: scores the graded test binaries; checks the stubs and the mutants", "pt-grade"};
  app.require_subcommand(1);
  app.footer(
      "Each binary's output goes to BINARY.grade.log. Time limits: --test-timeout per test, --part-budget per part,\n"
      "--budget for all parts (defaults below). The sandbox's layers: pt-grade sandbox.\n"
      "Exit status: 0 graded (whatever the score) or check passed, 1 check failed, 2 could not grade.");
  Common common;
  common.opt.sandbox.readable = {build_paths::grade_readable()};
  const std::vector<Command> commands{
      add_run(app, common),
      add_check(app, common, "check-stubs", "every graded test must fail naming a task of the part",
                "test binary built from the untouched stubs", check_stubs, false),
      add_check(app, common, "check-mutant", "at least one graded test must fail", "test binary built with a mutant",
                check_mutant, true),
      add_manifest(app),
      add_submission(app, common),
      add_check_submission(app, common),
      add_sandbox(app, common)};

  // `run` is the default: insert it when the first argument is an option.
  std::vector<char*> args(argv, argv + argc);
  std::string run_word = "run";
  if (argc == 1 || (argv[1][0] == '-' && std::strcmp(argv[1], "-h") != 0 && std::strcmp(argv[1], "--help") != 0))
    args.insert(args.begin() + 1, run_word.data());
  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  scrub_gtest_environment();
  hide_command_line(argc, argv, "pt-grade");
  try {
    for (const Command& c : commands) {
      if (!*c.cmd) continue;
      // Without the sandbox (a build off Linux) only the student's own check
      // runs code, and the manifest lists the course's own binaries.
      const std::string name = c.cmd->get_name(), missing = sandbox_unavailable();
      if (!missing.empty() && name != "check-submission" && name != "manifest") {
        std::fprintf(stderr,
                     "pt-grade %s: grading needs Linux's sandbox, which this build does not have (PT_SANDBOX is off): "
                     "run it on your course's grader, in WSL or in the dev container (.devcontainer/); here, "
                     "pt-grade check-submission checks your task files.\n",
                     name.c_str());
        return 2;
      }
      return c.action();
    }
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-grade: %s\n", e.what());
    return 2;
  }
}
