// pt-grade: scores the graded GoogleTest binaries (DESIGN.md section 6) and
// checks the stubs and the mutant gallery with the same machinery.
//
// A binary runs once with --pt_results, which streams one result line per
// finished test, so a crash or a hang loses nothing that already finished. The
// graded tests left without a result are then run one at a time under their own
// timeout: a crash or a hang costs only the points of the test that caused it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "process.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using pt::grade::Exit;

struct Limits {
  double binary = 600, test = 60;
  // Stop a binary at its first failing test (check-mutant only needs one):
  // keeps the mutant gallery's CI time proportional to the catch, not the suite.
  bool fail_fast = false;
};

struct GradedTest {
  std::string name, task;
  double points = 0;
  bool hidden = false;

  bool passed = false, skipped = false;
  bool died = false;    // crashed, hung or exited without reporting a result
  std::string message;  // GoogleTest's failure text, or how the process ended
  std::string output;   // the last lines it printed, when it died
};

struct BinaryReport {
  std::string binary, log;
  std::string error;  // the graded tests could not even be listed
  std::string note;   // the full run did not report every graded test
  Exit full;
  std::vector<GradedTest> tests;
};

class TempFile {
 public:
  TempFile() {
    const char* dir = std::getenv("TMPDIR");
    std::string pattern = std::string(dir && *dir ? dir : "/tmp") + "/pt-grade-XXXXXX";
    const int fd = ::mkstemp(pattern.data());
    if (fd >= 0) {
      ::close(fd);
      path_ = pattern;
    }
  }
  ~TempFile() {
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The results come from code under test: any field may be missing or mistyped.
std::string get_string(const json& j, const char* key) {
  auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : "";
}
double get_number(const json& j, const char* key) {
  auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : 0.0;
}
bool get_bool(const json& j, const char* key) {
  auto it = j.find(key);
  return it != j.end() && it->is_boolean() && it->get<bool>();
}

std::vector<json> read_json_lines(const std::string& path) {
  std::vector<json> objects;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    json j = json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (j.is_object()) objects.push_back(std::move(j));
  }
  return objects;
}

std::map<std::string, json> read_results(const std::string& path) {
  std::map<std::string, json> by_name;
  for (auto& j : read_json_lines(path))
    if (auto name = get_string(j, "test"); !name.empty()) by_name[name] = std::move(j);
  return by_name;
}

void record(GradedTest& t, const json& result) {
  t.passed = get_bool(result, "passed");
  t.skipped = get_bool(result, "skipped");
  t.message = get_string(result, "message");
  if (!t.passed && t.message.empty())
    t.message = t.skipped ? "skipped (a skipped test earns no points)" : "failed without a message";
  constexpr size_t kMaxMessage = 20000;  // a failing EXPECT in a loop can write megabytes
  if (t.message.size() > kMaxMessage) t.message = t.message.substr(0, kMaxMessage) + "\n... (truncated)";
}

std::string first_lines(const std::string& text, size_t count, const std::string& indent) {
  std::string out;
  size_t pos = 0, shown = 0;
  while (pos < text.size() && shown < count) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(pos, std::min<size_t>(end - pos, 240));
    out += indent + line + (end - pos > 240 ? " ..." : "") + "\n";
    pos = end + 1;
    ++shown;
  }
  if (pos < text.size()) {
    const auto rest = std::count(text.begin() + static_cast<long>(pos), text.end(), '\n') + 1;
    out += indent + "... (" + std::to_string(rest) + " more lines)\n";
  }
  return out;
}

// The last lines a dying test wrote to the log after `offset`, without the
// banners (GoogleTest's and ours), which say nothing about why it died.
std::string output_since(const std::string& log, uintmax_t offset, size_t max_lines = 12) {
  std::error_code ec;
  const uintmax_t size = fs::file_size(log, ec);
  if (ec || size <= offset) return "";
  std::ifstream in(log, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(std::max<uintmax_t>(offset, size > 65536 ? size - 65536 : 0)));
  std::deque<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("[==", 0) == 0 || line.rfind("[--", 0) == 0 || line.rfind("[ RUN", 0) == 0 ||
        line.rfind("Note: Google Test filter", 0) == 0 || line.rfind("===== pt-grade:", 0) == 0)
      continue;
    lines.push_back(line.size() > 240 ? line.substr(0, 240) + " ..." : line);
    if (lines.size() > max_lines) lines.pop_front();
  }
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : "\n") + l;
  return out;
}

Exit run_logged(const std::vector<std::string>& argv, const std::string& out, const std::string& log, double timeout) {
  std::string command;
  for (const auto& a : argv) command += " " + a;
  std::ofstream(log, std::ios::app) << "\n===== pt-grade:" << command << "\n";
  return pt::grade::run_process(argv, out, log, timeout);
}

void run_alone(const std::string& binary, GradedTest& t, const std::string& log, double timeout) {
  std::clog << "pt-grade: running " << t.name << " on its own\n";
  TempFile results;
  std::error_code ec;
  const uintmax_t offset = fs::file_size(log, ec);
  const Exit e = run_logged({binary, "--gtest_filter=" + t.name, "--pt_results=" + results.path()}, log, log, timeout);
  const auto found = read_results(results.path());
  if (auto it = found.find(t.name); it != found.end()) return record(t, it->second);
  t.passed = false;
  t.died = true;
  t.message = e.how == Exit::How::Exited ? e.describe() + " before reporting a result" : e.describe();
  t.output = output_since(log, ec ? 0 : offset);
}

BinaryReport grade_binary(const std::string& binary, const Limits& limits) {
  BinaryReport rep;
  rep.binary = binary;
  if (!fs::is_regular_file(binary)) {
    rep.error = binary + " not found";
    return rep;
  }
  rep.log = binary + ".grade.log";
  std::ofstream(rep.log, std::ios::trunc);
  TempFile listing, results;
  if (listing.path().empty() || results.path().empty()) {
    rep.error = "cannot create temporary files (TMPDIR)";
    return rep;
  }
  const Exit listed = run_logged({binary, "--pt_list_graded"}, listing.path(), rep.log, limits.test);
  if (!listed.exited_ok()) {
    rep.error = "could not list the graded tests: " + listed.describe() + " (log: " + rep.log + ")";
    return rep;
  }
  std::set<std::string> seen;
  for (const auto& j : read_json_lines(listing.path())) {
    GradedTest t;
    t.name = get_string(j, "test");
    if (t.name.empty() || !seen.insert(t.name).second) continue;
    t.task = get_string(j, "task");
    t.points = get_number(j, "points");
    t.hidden = get_string(j, "visibility") == "hidden";
    rep.tests.push_back(std::move(t));
  }
  if (rep.tests.empty()) return rep;

  std::clog << "pt-grade: running " << binary << " (" << rep.tests.size() << " graded tests)\n";
  std::vector<std::string> args = {binary, "--pt_results=" + results.path()};
  if (limits.fail_fast) args.push_back("--gtest_fail_fast");
  rep.full = run_logged(args, rep.log, rep.log, limits.binary);
  // With --gtest_fail_fast, GoogleTest still reports every test it does not
  // run, as skipped: the results stay complete and need no special case.
  const auto found = read_results(results.path());
  size_t missing = 0;
  for (const auto& t : rep.tests) missing += found.count(t.name) == 0;
  if (missing > 0)
    rep.note = fs::path(binary).filename().string() + " " + rep.full.describe() + "; the " + std::to_string(missing) +
               " graded test(s) it left without a result were run one at a time";
  for (auto& t : rep.tests) {
    if (auto it = found.find(t.name); it != found.end())
      record(t, it->second);
    else
      run_alone(binary, t, rep.log, limits.test);
  }
  return rep;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string points_text(double v) { return fmt(v) + (v == 1 ? " point" : " points"); }

// ---- pt-grade run ----------------------------------------------------------

struct Part {
  int number;
  BinaryReport rep;
};

struct Tally {
  int passed = 0, total = 0;
  double earned = 0, possible = 0;
  void add(const GradedTest& t) {
    ++total;
    passed += t.passed;
    earned += t.passed ? t.points : 0;
    possible += t.points;
  }
  std::string tests() const { return std::to_string(passed) + " / " + std::to_string(total); }
  std::string points() const { return fmt(earned) + " / " + fmt(possible); }
};

void print_report(const std::vector<Part>& parts, const std::vector<std::string>& notes, bool show_hidden) {
  std::printf("\n%-6s %-14s %s\n", "part", "tests passed", "points");
  Tally all;
  for (const auto& p : parts) {
    if (!p.rep.error.empty()) {
      std::printf("%-6d %s\n", p.number, p.rep.error.c_str());
      continue;
    }
    Tally part, hidden;
    for (const auto& t : p.rep.tests) {
      part.add(t);
      all.add(t);
      if (t.hidden) hidden.add(t);
    }
    const std::string extra =
        hidden.total == 0 ? "" : "including hidden: " + hidden.tests() + " tests, " + hidden.points() + " points";
    std::printf("%-6d %-14s %-14s %s\n", p.number, part.tests().c_str(), part.points().c_str(), extra.c_str());
  }
  std::printf("%-6s %-14s %s\n", "total", all.tests().c_str(), all.points().c_str());

  bool header = false;
  for (const auto& p : parts) {
    bool failed = false;
    for (const auto& t : p.rep.tests) {
      if (t.passed) continue;
      if (!header) std::printf("\nFailed graded tests:\n");
      header = failed = true;
      if (t.hidden && !show_hidden) {
        std::printf("  %s (hidden test, %s)\n", t.task.c_str(), points_text(t.points).c_str());
        continue;
      }
      std::printf("  %s %s%s (%s)\n", t.task.c_str(), t.name.c_str(), t.hidden ? " [hidden]" : "",
                  points_text(t.points).c_str());
      std::fputs(first_lines(t.message, 6, "      ").c_str(), stdout);
      if (!t.output.empty()) {
        std::printf("      last output:\n");
        std::fputs(first_lines(t.output, 12, "      | ").c_str(), stdout);
      }
    }
    if (failed) std::printf("      (part %d output: %s)\n", p.number, p.rep.log.c_str());
  }
  if (!notes.empty()) std::printf("\nNotes:\n");
  for (const auto& n : notes) std::printf("  %s\n", n.c_str());
  std::fflush(stdout);
}

bool write_gradescope(const std::string& path, const std::vector<Part>& parts, const std::vector<std::string>& notes,
                      double seconds) {
  json tests = json::array();
  double score = 0;
  for (const auto& p : parts) {
    if (!p.rep.error.empty())
      tests.push_back({{"name", "Part " + std::to_string(p.number)},
                       {"score", 0},
                       {"max_score", 0},
                       {"status", "failed"},
                       {"output", p.rep.error}});
    for (const auto& t : p.rep.tests) {
      std::string output = t.passed ? "" : t.message;
      if (!t.output.empty()) output += "\n\nLast output before it stopped:\n" + t.output;
      score += t.passed ? t.points : 0;
      tests.push_back({{"name", t.task + " " + t.name},
                       {"score", t.passed ? t.points : 0.0},
                       {"max_score", t.points},
                       {"status", t.passed ? "passed" : "failed"},
                       {"output", output},
                       {"visibility", t.hidden ? "after_published" : "visible"}});
    }
  }
  json doc = {{"score", score}, {"execution_time", std::round(seconds * 10) / 10}, {"tests", tests}};
  std::string text;
  for (const auto& n : notes) text += n + "\n";
  if (!text.empty()) doc["output"] = text;
  std::ofstream out(path);
  // Messages and output are whatever the tests printed: never let bad UTF-8 stop the report.
  out << doc.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
  return static_cast<bool>(out.flush());
}

int run(const std::string& build_dir, const std::vector<int>& numbers, const Limits& limits,
        const std::string& json_path, bool show_hidden) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Part> parts;
  std::vector<std::string> notes;
  for (int n : numbers) {
    const std::string binary = (fs::path(build_dir) / "tests" / ("part" + std::to_string(n) + "_tests")).string();
    if (!fs::is_regular_file(binary)) {
      notes.push_back("part " + std::to_string(n) + ": " + binary + " not found, not graded");
      continue;
    }
    parts.push_back({n, grade_binary(binary, limits)});
    if (!parts.back().rep.note.empty()) notes.push_back("part " + std::to_string(n) + ": " + parts.back().rep.note);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (parts.empty())
    notes.push_back("no test binaries found under " + build_dir + "/tests: build them first");
  else
    print_report(parts, notes, show_hidden);
  if (!json_path.empty() && !write_gradescope(json_path, parts, notes, seconds)) {
    std::fprintf(stderr, "pt-grade: cannot write %s\n", json_path.c_str());
    return 2;
  }
  if (parts.empty()) {
    for (const auto& n : notes) std::fprintf(stderr, "pt-grade: %s\n", n.c_str());
    return 2;
  }
  return 0;
}

// ---- pt-grade check-stubs / check-mutant -----------------------------------

int check_stubs(int part, const std::string& binary, const Limits& limits) {
  const BinaryReport rep = grade_binary(binary, limits);
  if (!rep.error.empty()) {
    std::printf("check-stubs: %s: %s\n", binary.c_str(), rep.error.c_str());
    return 2;
  }
  const std::string prefix = "P" + std::to_string(part) + "T";
  const std::string wanted = "not implemented: " + prefix;
  std::vector<std::string> problems;
  if (rep.tests.empty()) problems.push_back("the binary declares no graded test");
  if (rep.full.died())
    problems.push_back("the full run " + rep.full.describe() + ": the stubs must neither crash nor hang");
  for (const auto& t : rep.tests) {
    const std::string first = t.message.substr(0, t.message.find('\n'));
    if (t.task.rfind(prefix, 0) != 0)
      problems.push_back(t.name + ": its task " + t.task + " is not a part " + std::to_string(part) + " task");
    if (t.passed)
      problems.push_back(t.name + " (" + t.task + "): passed");
    else if (t.died)
      problems.push_back(t.name + " (" + t.task + "): " + t.message);
    else if (t.message.find(wanted) == std::string::npos)
      problems.push_back(t.name + " (" + t.task + "): fails without \"" + wanted + "\": " + first);
  }
  if (problems.empty()) {
    std::printf("stubs OK: all %zu graded tests of part %d fail with \"%s...\"\n", rep.tests.size(), part,
                wanted.c_str());
    return 0;
  }
  std::printf("stubs check failed for %s:\n", binary.c_str());
  for (const auto& p : problems) std::fputs(first_lines(p, 4, "  ").c_str(), stdout);
  std::printf("(output: %s)\n", rep.log.c_str());
  return 1;
}

int check_mutant(const std::string& binary, const Limits& limits) {
  const BinaryReport rep = grade_binary(binary, limits);
  if (!rep.error.empty()) {
    std::printf("check-mutant: %s: %s\n", binary.c_str(), rep.error.c_str());
    return 2;
  }
  std::vector<const GradedTest*> caught;
  for (const auto& t : rep.tests)
    if (!t.passed && !t.skipped) caught.push_back(&t);
  if (caught.empty()) {
    std::printf("mutant survived: no graded test failed (%zu graded tests ran)\n", rep.tests.size());
    return 1;
  }
  std::printf("mutant caught by %zu of %zu graded tests:\n", caught.size(), rep.tests.size());
  for (const auto* t : caught) {
    const std::string first = t->message.substr(0, t->message.find('\n'));
    std::printf("  %s %s: %s\n", t->task.c_str(), t->name.c_str(), first.substr(0, 200).c_str());
  }
  return 0;
}

// A GTEST_FILTER or GTEST_REPEAT left in the environment would silently change
// what gets graded.
void scrub_gtest_environment() {
  std::vector<std::string> names;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "GTEST_", 6) == 0) {
      const char* eq = std::strchr(*e, '=');
      names.emplace_back(*e, eq ? static_cast<size_t>(eq - *e) : std::strlen(*e));
    }
  for (const auto& n : names) ::unsetenv(n.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pt-grade: scores the graded test binaries; checks the stubs and the mutants", "pt-grade"};
  app.require_subcommand(1);
  app.footer(
      "The output of each binary goes to BINARY.grade.log.\n"
      "Exit status: 0 graded (whatever the score) or check passed, 1 check failed, 2 could not grade.");
  Limits limits;
  const CLI::Validator seconds(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        return *end == '\0' && v > 0 && v <= 1e6 ? "" : "expected a number of seconds in (0, 1e6], got " + text;
      },
      "");
  auto add_limits = [&](CLI::App* cmd) {
    cmd->add_option("--timeout", limits.binary, "time allowed to a whole test binary")
        ->check(seconds)
        ->type_name("SECONDS")
        ->capture_default_str();
    cmd->add_option("--test-timeout", limits.test, "time allowed to one test re-run on its own")
        ->check(seconds)
        ->type_name("SECONDS")
        ->capture_default_str();
  };

  std::string build_dir = "build", json_path;
  std::vector<int> parts{1, 2, 3, 4, 5};
  bool show_hidden = false;
  CLI::App* run_cmd = app.add_subcommand("run", "grade DIR/tests/partN_tests of each part (the default)");
  run_cmd->add_option("--build-dir", build_dir, "build directory")->type_name("DIR")->capture_default_str();
  run_cmd->add_option("--parts", parts, "parts to grade")->delimiter(',')->type_name("N,...")->capture_default_str();
  add_limits(run_cmd);
  run_cmd->add_option("--json", json_path, "write a Gradescope results.json")->type_name("FILE");
  run_cmd->add_flag("--hidden", show_hidden, "show the names and failures of hidden tests too");

  int part = 0;
  std::string binary;
  CLI::App* stubs_cmd = app.add_subcommand("check-stubs", "every graded test must fail naming a task of the part");
  stubs_cmd->add_option("--part", part, "the part the binary tests")
      ->required()
      ->check(CLI::Range(1, 99))
      ->type_name("N");
  stubs_cmd->add_option("BINARY", binary, "test binary built from the untouched stubs")
      ->required()
      ->check(CLI::ExistingFile);
  add_limits(stubs_cmd);

  CLI::App* mutant_cmd = app.add_subcommand("check-mutant", "at least one graded test must fail");
  mutant_cmd->add_option("BINARY", binary, "test binary built with a mutant")->required()->check(CLI::ExistingFile);
  add_limits(mutant_cmd);
  mutant_cmd->add_flag("--fail-fast", limits.fail_fast, "stop at the first failing test (lists only that one)");

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
  try {
    if (*stubs_cmd) return check_stubs(part, binary, limits);
    if (*mutant_cmd) return check_mutant(binary, limits);
    return run(build_dir, parts, limits, json_path, show_hidden);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-grade: %s\n", e.what());
    return 2;
  }
}
