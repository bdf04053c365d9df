#include "submission/check_submission.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "compile/dependency_check.h"
#include "intake/ignore_rules.h"
#include "intake/submission_files.h"
#include "process/command.h"
#include "report/check_answer.h"
#include "report/classroom_result.h"
#include "report/report_text.h"
#include "run/manifest.h"
#include "submission/pipeline.h"

namespace pt::grade {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json read_facts(const fs::path& source) {
  const fs::path path = source / "prebuilt" / "release.json";
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + " not found: check-submission works in the student release only "
                                                    "(in a course checkout, build the grader-kit and use pt-grade submission)");
  return json::parse(in);
}

std::string indented(const std::string& text) { return folded(text, "   "); }

// Whether the grader runs part `part`'s tests in a verifier and its task code
// in a worker (boundary/README.md), as this build was configured.
bool across_boundary(int part) {
  return std::string("," PT_BOUNDARY_PARTS ",").find("," + std::to_string(part) + ",") != std::string::npos;
}

// SHA-256 of each file by coreutils' sha256sum (one run for all of them);
// a file that cannot be read is left out.
std::map<std::string, std::string> sha256_of(const fs::path& source, const std::vector<std::string>& files) {
  std::map<std::string, std::string> hashes;
  std::vector<std::string> argv{"sha256sum", "--"};
  for (const auto& f : files)
    if (fs::is_regular_file(source / f)) argv.push_back((source / f).string());
  if (argv.size() == 2) return hashes;
  std::string out;
  run_command(argv, &out);
  std::istringstream in(out);
  const std::string prefix = source.string() + "/";
  for (std::string line; std::getline(in, line);) {
    if (line.size() < 67 || line[64] != ' ') continue;
    std::string path = line.substr(66);
    if (path.rfind(prefix, 0) == 0) path = path.substr(prefix.size());
    hashes[path] = line.substr(0, 64);
  }
  return hashes;
}

// Step 3: every shipped file the grader has its own copy of, as shipped; and
// nothing added where the build globs for sources, less what the release's
// .gitignore ignores (node_modules/ after the viewer test's `npm ci`, renders).
std::vector<std::string> edited_files(const fs::path& source, const json& shipped) {
  std::vector<std::string> names, problems;
  for (const auto& [name, hash] : shipped.items()) names.push_back(name);
  const auto now = sha256_of(source, names);
  for (const auto& [name, hash] : shipped.items()) {
    auto it = now.find(name);
    if (it == now.end())
      problems.push_back(name + ": missing");
    else if (it->second != hash.get<std::string>())
      problems.push_back(name + ": edited");
  }
  const IgnoreRules ignore = IgnoreRules::read((source / ".gitignore").string());
  for (const char* dir : {"skeleton", "tests"}) {
    if (!fs::is_directory(source / dir)) continue;
    for (auto it = fs::recursive_directory_iterator(source / dir); it != fs::recursive_directory_iterator(); ++it) {
      const std::string rel = fs::relative(it->path(), source).generic_string();
      if (it->is_directory() && ignore.ignored(rel, true)) {
        it.disable_recursion_pending();
        continue;
      }
      if (it->is_regular_file() && !shipped.contains(rel) && !ignore.ignored(rel, false))
        problems.push_back(rel + ": added");
    }
  }
  return problems;
}

// The visible points of the build's manifest (0 when it has none yet): what a
// result that stopped early is out of.
double visible_points(const fs::path& build) {
  try {
    Manifest m = read_manifest((build / "tests" / "graded_manifest.json").string());
    leave_extensions_uncounted(m);
    double sum = 0;
    for (const auto& [part, tests] : m.parts)
      for (const auto& t : tests) sum += t.hidden ? 0 : t.points;
    return sum;
  } catch (const std::exception&) {
    return 0;
  }
}

// With --format github-classroom, stdout carries the result alone: what the
// check prints for a person goes to stderr (the workflow's log) until the
// result is written to the stdout it had.
class ResultChannel {
 public:
  explicit ResultChannel(bool classroom) {
    if (!classroom) return;
    std::fflush(stdout);
    fd_ = ::dup(STDOUT_FILENO);
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
  }
  ~ResultChannel() { to_result(); }
  bool active() const { return fd_ >= 0; }
  void write(const std::string& text) {
    to_result();
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
  }

 private:
  void to_result() {
    if (fd_ < 0) return;
    std::fflush(stdout);
    ::dup2(fd_, STDOUT_FILENO);
    ::close(fd_);
    fd_ = -1;
  }
  int fd_ = -1;
};

}  // namespace

std::map<int, HiddenNotRun> hidden_not_run_in(const std::string& source_dir) {
  std::map<int, HiddenNotRun> hidden;
  std::ifstream in(fs::path(source_dir) / "prebuilt" / "release.json");
  if (!in) return hidden;
  const json facts = json::parse(in);
  for (const auto& [part, h] : facts.at("hidden").items())
    hidden[std::stoi(part)] = {h.at("tests").get<int>(), h.at("hundredths_of_points").get<int>() / 100.0};
  return hidden;
}

namespace {

// The student's ending: the steps' details gathered while progress goes to
// stderr, each way the grader's result will differ from this one, and per
// part the grader's reason when it will not grade it.
class Answer : public Ending {
 public:
  void heading(const char* text) { details += std::string("\n== ") + text + "\n"; }

  void refused(const TaskFile& file, Stage stage, const std::string& why) override {
    details += indented(why);
    const char* what = stage == Stage::Directives ? ": rejected before building (step 2)"
                       : stage == Stage::Build  ? ": does not build (step 4)"
                       : stage == Stage::Reads  ? ": reads files the grader refuses (step 4)"
                                                : ": not built (step 1)";
    problems.push_back("part " + std::to_string(file.part) + what);
  }
  void accepted(const TaskFile& file) override { details += "   " + file.where + ": accepted\n"; }
  void built(const TaskFile& file, double seconds) override {
    details += "   part " + std::to_string(file.part) + ": built in " + number(seconds, "%.0f s") + "\n";
  }

  std::string details;
  std::vector<std::string> problems;  // each a way the grader's result will differ from this one
};

// Stage 3 in the release's own build: each part as the grader builds it (a
// worker of the task file and the tests' verifier beside it, here with the
// visible tests only, for a part across the process boundary), then the
// compiler's list of what it read, as the grader checks it.
class ReleaseBuild : public PartBuilder {
 public:
  ReleaseBuild(const fs::path& source, const fs::path& build, const std::string& shown, Answer& answer)
      : source_(source), build_(build), shown_(shown), answer_(answer) {}

  std::string build(const TaskFile& f, BuiltPart* built) override {
    const bool across = across_boundary(f.part);
    const std::string part = "part" + std::to_string(f.part);
    const std::string target = part + (across ? "_worker" : "_tests");
    const std::string also = across ? " " + part + "_verify" : "";
    answer_.details += "   $ cmake --build " + shown_ + " --target " + target + also + "\n";
    std::fprintf(stderr, "building part %d ...\n", f.part);
    std::vector<std::string> command{"cmake", "--build", build_.string(), "--target", target};
    if (across) command.push_back(part + "_verify");
    std::string out;
    if (run_command(command, &out) != 0)
      return f.where + " does not build: part " + std::to_string(f.part) + " scores 0.\n" +
             compiler_errors(out, source_.string());
    built->binary = (build_ / "tests" / (across ? part + "_verify" : target)).string();
    if (across) built->worker = (build_ / "tests" / target).string();
    return "";
  }

  // The task file, the framework's headers, the compiler's own, and what the
  // header probe (built with partN_tests) read.
  std::vector<std::string> unexpected_reads(const TaskFile& f) override {
    return unexpected_dependencies(build_.string(), "pt_part" + std::to_string(f.part) + "_student.dir/",
                                   {(source_ / "tasks").string() + "/", (source_ / "skeleton").string() + "/",
                                    "/usr/lib/gcc/"},
                                   "pt_header_probe.dir/");
  }

 private:
  const fs::path source_, build_;
  const std::string shown_;  // the build folder as the student named it
  Answer& answer_;
};

// Step 1's own check: steps 4 and 5 build and test the release's tasks/, so
// a submission elsewhere must be that.
void compare_with_tasks(const fs::path& source, const Submission& sub, Answer& answer) {
  for (const auto& f : sub.files) {
    answer.details += "   " + f.where + ": part " + std::to_string(f.part) + "\n";
    std::ifstream built(source / "tasks" / f.name, std::ios::binary);
    std::ostringstream text;
    text << built.rdbuf();
    if (!f.too_large && text.str() != f.text)
      answer.problems.push_back(f.where + " is not tasks/" + f.name + ", which is what steps 4 and 5 build and test");
  }
}

// Step 3: the files the grader has its own copy of.
void check_shipped_files(const fs::path& source, const json& facts, Answer& answer) {
  const auto edits = edited_files(source, facts.at("files"));
  if (edits.empty()) answer.details += "   skeleton/, tests/, prebuilt/ and the build files are as shipped\n";
  for (const auto& e : edits) answer.details += "   " + e + "\n";
  if (edits.empty()) return;
  answer.details += indented("The grader builds your task files with its own copy of these files, not yours: a task "
                             "file that needs your change will not build there, or behave as it does here. Undo the "
                             "change (e.g. from the release's tarball) and move what you need into your task file.");
  answer.problems.push_back(std::to_string(edits.size()) + " file(s) the grader has its own copy of differ (step 3)");
}

// Step 5: every part of the manifest, graded where it was built.
Report grade_visible(const CheckOptions& opt, const Manifest& manifest, const fs::path& source, const fs::path& build,
                     const Pipeline& pipeline) {
  Report report;
  report.hidden_not_run = hidden_not_run_in(source.string());
  Sandbox sandbox(opt.sandbox);
  // A failing image test's images stay in the build folder, where its
  // message names them (in a sandbox's own folder they would be gone).
  int image_runs = 0;
  const fs::path image_root = build / "image_test_failures";
  ImageFolders kept_images{[&](std::string* error) {
                             const fs::path dir = image_root / ("run-" + std::to_string(++image_runs));
                             std::error_code ec;
                             fs::create_directories(dir, ec);
                             if (ec) *error = dir.string() + ": " + ec.message();
                             return ec ? std::string() : dir.string();
                           },
                           [](const std::string&) {}, true};
  std::error_code gone;
  fs::remove_all(image_root, gone);  // only this check's images, none of an earlier one
  pipeline.grade(manifest, opt.limits, sandbox, Redactor(), &kept_images, report);
  report.complete = true;
  return report;
}

// Without the sandbox (a build off Linux: PT_SANDBOX), what this check
// cannot do, first: its READY is about what it checked.
void print_not_checked() {
  if (sandbox_unavailable().empty()) return;
  std::fputs("Not checked on this platform (this pt-grade has no sandbox: it needs Linux); the grader checks each:\n"
             "  - the sandbox: tests run here as plain processes, so code that forks, writes outside its\n"
             "    folder, or outgrows the grader's limits passes here and fails there;\n"
             "  - the process boundary: here each part's tests and its task file run in one process; the grader\n"
             "    runs your task functions in a worker process of their own;\n"
             "  - pt-link-guard: what your task file's compiled code defines and calls;\n"
             "  - the hidden tests (as on every platform: the release does not have them).\n"
             "A READY here means ready as far as these checks go. For the grader's own checks: WSL, the dev\n"
             "container (.devcontainer/) or your course's GitHub Classroom run.\n\n",
             stdout);
}

// The answer first: per part, whose the file is, its visible score, what
// differs; then how the check found it; the parts not started folded.
void print_check(const Report& report, const Pipeline& pipeline, const Answer& answer) {
  std::vector<PartAnswer> answers;
  Report started = report;  // the parts whose failures say something: all but the untouched
  started.parts.clear();
  std::string folded_parts;
  for (const auto& part : report.parts) {
    PartAnswer a{part.part, "", part.earned(), part.possible(), {}, ""};
    if (auto h = report.hidden_not_run.find(part.part); h != report.hidden_not_run.end()) a.hidden = h->second;
    const TaskFile* file = nullptr;
    for (const auto& f : pipeline.submission().files)
      if (f.part == part.part) file = &f;
    if (!file) {
      a.state = "not submitted";
    } else if (!part.graded) {
      a.state = "not graded: see step " + std::string(pipeline.built().count(part.part) ? "5" : "2 or 4");
      a.differs = "scores 0";
    } else if (untouched(part)) {
      a.state = "not started";
    } else {
      a.state = task_file_state(file->text);
    }
    if (untouched(part)) {
      folded_parts += "  part " + std::to_string(part.part) + ": not started: its " + std::to_string(part.tests.size()) +
                      " visible tests fail with \"not implemented\" (./build/tests/part" + std::to_string(part.part) +
                      "_tests lists them)\n";
    } else {
      started.parts.push_back(part);
    }
    answers.push_back(a);
  }
  print_not_checked();
  print_answer(answers, answer.problems, sandbox_unavailable().empty());
  std::printf("\nHow this check found it:\n");
  std::fputs(answer.details.c_str(), stdout);
  if (!started.parts.empty()) print_report(started, false);
  if (!folded_parts.empty()) std::printf("\nParts not started (folded):\n%s", folded_parts.c_str());
  std::fflush(stdout);
}

}  // namespace

int check_submission(const CheckOptions& opt) {
  const fs::path source = fs::absolute(opt.source_dir), build = fs::absolute(opt.build_dir);
  ResultChannel result(opt.format == "github-classroom");
  // A check that stopped before any test ran: its result for GitHub Classroom says why.
  const auto stopped = [&](const char* status, const std::string& what, const std::string& why, double points) {
    if (result.active()) result.write(classroom_stopped(status, what, why, points));
  };
  const json facts = read_facts(source);
  if (!fs::is_regular_file(build / "CMakeCache.txt")) {
    std::fprintf(stderr, "pt-grade: %s is not a configured build: set up the release first (README: Set up)\n",
                 build.c_str());
    stopped("error", "pt-grade check-submission: could not check", build.string() + " is not a configured build", 0);
    return 2;
  }
  std::map<int, std::string> expected;
  std::set<int> parts;
  for (const auto& [part, name] : facts.at("task_files").items()) {
    expected[std::stoi(part)] = name.get<std::string>();
    parts.insert(std::stoi(part));
  }

  Answer answer;
  Pipeline pipeline(expected, parts, answer);
  std::printf("pt-grade check-submission %s: what the grader will do with these files.\n", opt.tasks.c_str());
  answer.heading("1. The files, taken as the grader takes them");
  const bool taken = pipeline.take_files(opt.tasks);
  const Submission& sub = pipeline.submission();
  for (const auto& n : sub.notes) answer.details += indented(n);
  if (!taken) {
    print_not_checked();
    const std::string why = pipeline.rejection();
    std::fputs(indented(why).c_str(), stdout);
    std::printf("\nNOT READY: the grader would reject every part. Nothing was built.\n");
    stopped("fail", "The files: the grader would reject every part", why, visible_points(build));
    return 1;
  }
  compare_with_tasks(source, sub, answer);
  answer.heading("2. What each file reads as data (#embed, the assembler's .incbin)");
  pipeline.check_directives();
  answer.heading("3. The files the grader has its own copy of");
  check_shipped_files(source, facts, answer);
  answer.heading("4. Each part built on its own, as the grader builds it");
  ReleaseBuild release_build(source, build, opt.build_dir, answer);
  pipeline.build(release_build);
  if (!sandbox_unavailable().empty())
    answer.details += "   not checked here: pt-link-guard (it needs Linux); the grader runs it on each part's object\n";

  answer.heading("5. The visible tests");
  if (!sandbox_unavailable().empty())
    answer.details += "   run here as plain processes, each part's tests with its task file in one process; the grader "
                      "runs them in its sandbox, across the process boundary\n";
  const fs::path manifest_path = build / "tests" / "graded_manifest.json";
  if (!fs::is_regular_file(manifest_path)) {
    std::printf("   %s not found: build the release first (README: Set up)\n", manifest_path.c_str());
    stopped("error", "pt-grade check-submission: could not check",
            manifest_path.string() + " not found: the release is not built", 0);
    return 2;
  }
  // The student cannot know whether the instructor counts the extension
  // tasks, so they are shown at 0 points, as the grader shows them by default.
  Manifest manifest = read_manifest(manifest_path.string());
  leave_extensions_uncounted(manifest);
  const Report report = grade_visible(opt, manifest, source, build, pipeline);
  print_check(report, pipeline, answer);
  if (result.active()) {
    std::map<int, ClassroomFile> files;
    for (const auto& f : sub.files) files[f.part] = {"tasks/" + f.name, f.text};
    result.write(classroom_result(report, files, index_handouts((source / "handouts").string()), answer.problems));
  }
  return answer.problems.empty() ? 0 : 1;
}

}  // namespace pt::grade
