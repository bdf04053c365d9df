#include "submission/check_submission.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "intake/ignore_rules.h"
#include "intake/submission_files.h"
#include "process/command.h"
#include "report/check_answer.h"
#include "report/classroom_result.h"
#include "run/manifest.h"
#include "submission/submission.h"

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
  std::istringstream parts(PT_BOUNDARY_PARTS);
  for (std::string p; std::getline(parts, p, ',');)
    if (p == std::to_string(part)) return true;
  return false;
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

int check_submission(const CheckOptions& opt) {
  const fs::path source = fs::absolute(opt.source_dir), build = fs::absolute(opt.build_dir);
  ResultChannel result(opt.format == "github-classroom");
  const json facts = read_facts(source);
  if (!fs::is_regular_file(build / "CMakeCache.txt")) {
    std::fprintf(stderr, "pt-grade: %s is not a configured build: set up the release first (README: Set up)\n",
                 build.c_str());
    if (result.active())
      result.write(classroom_stopped("error", "pt-grade check-submission: could not check",
                                     build.string() + " is not a configured build", 0));
    return 2;
  }
  std::map<int, std::string> expected;
  for (const auto& [part, name] : facts.at("task_files").items()) expected[std::stoi(part)] = name.get<std::string>();
  std::set<std::string> headers;
  for (const auto& [name, hash] : facts.at("files").items())
    if (name.rfind("skeleton/", 0) == 0 && fs::path(name).extension() == ".h") headers.insert(name.substr(9));
  std::vector<std::string> problems;  // each a way the grader's result will differ from this one
  std::map<int, std::string> not_graded;  // part -> the grader's reason

  // The answer comes first, the steps that found it after: they are
  // gathered here while progress goes to stderr.
  std::string details;
  auto say = [&details](const char* format, auto... args) {
    char line[4096];
    std::snprintf(line, sizeof line, format, args...);
    details += line;
  };
  auto heading = [&details](const char* text) { details += std::string("\n== ") + text + "\n"; };
  std::printf("pt-grade check-submission %s: what the grader will do with these files.\n", opt.tasks.c_str());
  heading("1. The files, taken as the grader takes them");
  const Submission sub = read_submission(opt.tasks, expected);
  for (const auto& n : sub.notes) details += indented(n);
  if (!sub.problems.empty()) {
    std::string why = "submission rejected before building:";
    for (const auto& p : sub.problems) why += "\n  " + p;
    std::fputs(indented(why).c_str(), stdout);
    std::printf("\nNOT READY: the grader would reject every part. Nothing was built.\n");
    if (result.active())
      result.write(classroom_stopped("fail", "The files: the grader would reject every part", why,
                                     visible_points(build)));
    return 1;
  }
  std::set<int> submitted;
  for (const auto& f : sub.files) {
    say("   %s: part %d\n", f.where.c_str(), f.part);
    submitted.insert(f.part);
    // Step 4 builds the release's tasks/: a submission elsewhere must be that.
    std::ifstream built(source / "tasks" / f.name, std::ios::binary);
    std::ostringstream text;
    text << built.rdbuf();
    if (!f.too_large && text.str() != f.text)
      problems.push_back(f.where + " is not tasks/" + f.name + ", which is what steps 4 and 5 build and test");
  }
  for (const auto& [part, name] : expected)
    if (!submitted.count(part)) not_graded[part] = "not submitted: no " + name + " in the submission";

  heading("2. What each file includes (the grader's allowlist)");
  std::vector<const TaskFile*> buildable;
  for (const auto& f : sub.files) {
    const std::string rejected = intake_rejection(f, headers, nullptr);
    if (rejected.empty()) {
      say("   %s: accepted\n", f.where.c_str());
      buildable.push_back(&f);
      continue;
    }
    details += indented(rejected);
    not_graded[f.part] = rejected;
    problems.push_back("part " + std::to_string(f.part) + ": rejected before building (step 2)");
  }

  heading("3. The files the grader has its own copy of");
  const auto edits = edited_files(source, facts.at("files"));
  if (edits.empty()) say("   skeleton/, tests/, prebuilt/ and the build files are as shipped\n");
  for (const auto& e : edits) say("   %s\n", e.c_str());
  if (!edits.empty()) {
    details += indented("The grader builds your task files with its own copy of these files, not yours: a task file "
                        "that needs your change will not build there, or behave as it does here. Undo the change "
                        "(e.g. from the release's tarball) and move what you need into your task file.");
    problems.push_back(std::to_string(edits.size()) + " file(s) the grader has its own copy of differ (step 3)");
  }

  heading("4. Each part built on its own, as the grader builds it");
  std::map<int, std::string> binaries, workers;
  for (const TaskFile* f : buildable) {
    // A part graded across the process boundary (boundary/README.md) is built
    // as the grader builds it: a worker of the task file, and the tests'
    // verifier beside it (here with the visible tests only).
    const bool across = across_boundary(f->part);
    const std::string part = "part" + std::to_string(f->part);
    const std::string target = part + (across ? "_worker" : "_tests");
    const std::string also = across ? " " + part + "_verify" : "";
    say("   $ cmake --build %s --target %s%s\n", opt.build_dir.c_str(), target.c_str(), also.c_str());
    std::fprintf(stderr, "building part %d ...\n", f->part);
    std::string out;
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::string> command{"cmake", "--build", build.string(), "--target", target};
    if (across) command.push_back(part + "_verify");
    const int rc = run_command(command, &out);
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (rc != 0) {
      const std::string why = f->where + " does not build: part " + std::to_string(f->part) + " scores 0.\n" +
                              compiler_errors(out, source.string());
      details += indented(why);
      not_graded[f->part] = why;
      problems.push_back("part " + std::to_string(f->part) + ": does not build (step 4)");
      continue;
    }
    // As the grader checks it: the task file, the framework's headers, the
    // compiler's own, and what the header probe (built with partN_tests) read.
    const auto unexpected =
        unexpected_dependencies(build.string(), "pt_part" + std::to_string(f->part) + "_student.dir/",
                                {(source / "tasks").string() + "/", (source / "skeleton").string() + "/",
                                 "/usr/lib/gcc/"},
                                "pt_header_probe.dir/");
    if (!unexpected.empty()) {
      std::string why = "while compiling " + f->where + " the compiler read files outside the framework's headers and "
                        "the standard library: rejected.\n";
      for (const auto& u : unexpected) why += "  " + u + "\n";
      details += indented(why);
      not_graded[f->part] = why;
      problems.push_back("part " + std::to_string(f->part) + ": reads files the grader refuses (step 4)");
      continue;
    }
    say("   part %d: built in %.0f s\n", f->part, std::round(took));
    if (across) {
      binaries[f->part] = (build / "tests" / (part + "_verify")).string();
      workers[f->part] = (build / "tests" / target).string();
    } else {
      binaries[f->part] = (build / "tests" / target).string();
    }
  }

  heading("5. The visible tests");
  const fs::path manifest_path = build / "tests" / "graded_manifest.json";
  if (!fs::is_regular_file(manifest_path)) {
    std::printf("   %s not found: build the release first (README: Set up)\n", manifest_path.c_str());
    if (result.active())
      result.write(classroom_stopped("error", "pt-grade check-submission: could not check",
                                     manifest_path.string() + " not found: the release is not built", 0));
    return 2;
  }
  // The student cannot know whether the instructor counts the extension
  // tasks, so they are shown at 0 points, as the grader shows them by default.
  Manifest manifest = read_manifest(manifest_path.string());
  leave_extensions_uncounted(manifest);
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
  for (const auto& [part, tests] : manifest.parts) {
    if (auto it = binaries.find(part); it != binaries.end())
      report.parts.push_back(grade_binary(part, it->second, tests, opt.limits, sandbox, it->second + ".grade.log",
                                          Redactor(), workers.count(part) ? workers.at(part) : "", &kept_images));
    else
      report.parts.push_back(pending_part(part, tests, not_graded.count(part) ? not_graded[part] : "not built"));
  }
  report.complete = true;

  // The answer: per part, whose the file is, its visible score, what differs.
  std::vector<PartAnswer> answers;
  Report started = report;  // the parts whose failures say something: all but the untouched
  started.parts.clear();
  std::string folded_parts;
  for (const auto& part : report.parts) {
    PartAnswer a;
    a.part = part.part;
    a.earned = part.earned();
    a.possible = part.possible();
    if (auto h = report.hidden_not_run.find(part.part); h != report.hidden_not_run.end()) a.hidden = h->second;
    const TaskFile* file = nullptr;
    for (const auto& f : sub.files)
      if (f.part == part.part) file = &f;
    if (!file) {
      a.state = "not submitted";
    } else if (!part.graded) {
      a.state = "not graded: see step " + std::string(binaries.count(part.part) ? "5" : "2 or 4");
      a.differs = "scores 0";
    } else if (untouched(part)) {
      a.state = "not started";
    } else {
      a.state = task_file_state(file->text);
    }
    if (untouched(part)) {
      int failed = 0;
      for (const auto& t : part.tests) failed += !t.passed();
      folded_parts += "  part " + std::to_string(part.part) + ": not started: its " + std::to_string(failed) +
                      " visible tests fail with \"not implemented\" (./build/tests/part" + std::to_string(part.part) +
                      "_tests lists them)\n";
    } else {
      started.parts.push_back(part);
    }
    answers.push_back(a);
  }
  print_answer(answers, problems);
  std::printf("\nHow this check found it:\n");
  std::fputs(details.c_str(), stdout);
  if (!started.parts.empty()) print_report(started, false);
  if (!folded_parts.empty()) std::printf("\nParts not started (folded):\n%s", folded_parts.c_str());
  std::fflush(stdout);
  if (result.active()) {
    std::map<int, ClassroomFile> files;
    for (const auto& f : sub.files) files[f.part] = {"tasks/" + f.name, f.text};
    result.write(classroom_result(report, files, index_handouts((source / "handouts").string()), problems));
  }
  return problems.empty() ? 0 : 1;
}

}  // namespace pt::grade
