#include "submission/submission.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "compile/kit_build.h"
#include "compile/work_area.h"
#include "intake/submission_files.h"
#include "process/command.h"
#include "report/html_report.h"
#include "report/leaderboard.h"
#include "report/prairielearn_report.h"
#include "report/redact.h"
#include "report/report.h"
#include "report/report_renders.h"
#include "report/report_text.h"
#include "run/manifest.h"
#include "source_scan.h"

namespace pt::grade {

namespace {

namespace fs = std::filesystem;

// The kit's tasks/ holds the untouched stubs: their names are the names a
// submission's files must have.
std::map<int, std::string> task_file_names(const fs::path& kit) {
  std::map<int, std::string> names;
  for (const auto& e : fs::directory_iterator(kit / "tasks")) {
    const std::string name = e.path().filename().string();
    int part = 0;
    if (std::sscanf(name.c_str(), "part%d_", &part) == 1 && e.path().extension() == ".cpp") names[part] = name;
  }
  return names;
}

std::set<std::string> framework_headers(const fs::path& kit) {
  std::set<std::string> headers;
  const fs::path include = kit / "include";
  for (const auto& e : fs::recursive_directory_iterator(include))
    if (e.is_regular_file()) headers.insert(fs::relative(e.path(), include).generic_string());
  return headers;
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

// A submission decides how many findings there are (a million refused lines):
// the first ones are listed, each capped, then how many more there are.
std::string joined_findings(const std::vector<SourceFinding>& found, const std::string& file) {
  std::vector<std::string> lines;
  for (const auto& f : found) lines.push_back(file + ":" + std::to_string(f.line) + ": " + f.what);
  return capped_list(lines, 100, 512);
}

}  // namespace

// What a failed build printed that a student needs: the compiler's errors
// first (with the lines that locate them), ninja's progress lines dropped.
std::string compiler_errors(const std::string& output, const std::string& tree_dir, size_t max_lines) {
  const fs::path tree = tree_dir;
  std::istringstream in(output);
  std::vector<std::string> kept;
  const std::string prefix = tree.string() + "/";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("[", 0) == 0 && line.find("] ") != std::string::npos && line.find("Building") != std::string::npos)
      continue;
    if (line.rfind("ninja: build stopped", 0) == 0 || line.rfind("FAILED: ", 0) == 0) continue;
    if (line.find("/usr/bin/c++") != std::string::npos || line.find("/usr/bin/g++") != std::string::npos) continue;
    // Paths relative to the tree: tasks/part1_...cpp:12:3: error: ...
    for (size_t at; (at = line.find(prefix)) != std::string::npos;) line.erase(at, prefix.size());
    kept.push_back(line.size() > 300 ? line.substr(0, 300) + " ..." : line);
  }
  // Start at the first error, if there is one (the compiler's, the linker's or
  // pt-link-guard's).
  size_t first = 0;
  for (size_t i = 0; i < kept.size(); ++i)
    if (kept[i].find("error") != std::string::npos || kept[i].find("undefined reference") != std::string::npos ||
        kept[i].find("multiple definition") != std::string::npos || kept[i].rfind("pt-link-guard:", 0) == 0) {
      first = i > 0 && kept[i - 1].find("In function") != std::string::npos ? i - 1 : i;
      break;
    }
  std::string text;
  for (size_t i = first; i < kept.size() && i < first + max_lines; ++i) text += kept[i] + "\n";
  if (kept.size() > first + max_lines) text += "... (" + std::to_string(kept.size() - first - max_lines) + " more lines)\n";
  return text;
}

std::string intake_rejection(const TaskFile& f, const std::set<std::string>& headers, std::string* flags) {
  if (f.too_large)
    return f.where + " is larger than " + std::to_string(kMaxTaskFileBytes >> 20) + " MiB: rejected before building";
  const SourceScan scan = scan_task_source(f.text, headers);
  if (flags && !scan.flags.empty())
    *flags = "source flags in " + f.where + " (the score is not affected):\n" + joined_findings(scan.flags, f.where);
  if (!scan.rejections.empty()) return f.where + " rejected before building:\n" + joined_findings(scan.rejections, f.where);
  return "";
}

namespace {

// What steps 1 to 3 leave for steps 4 to 6 (build_and_grade).
struct Graded {
  const SubmissionOptions& opt;
  const fs::path& kit;
  const Clock::time_point& deadline;
  const Manifest& manifest;
  const Redactor& redactor;
  const std::map<int, std::string>& expected;
  std::vector<const TaskFile*>& buildable;
  Report& report;
  HtmlReport& page;
  std::function<void()> save;
  std::function<void(int, const std::string&)> set_part;
  std::function<size_t(int)> part_index;
};

int build_and_grade(Graded& graded);

}  // namespace

int grade_submission(const SubmissionOptions& opt) {
  const auto start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(opt.budget_seconds));
  const fs::path kit = fs::absolute(opt.kit);
  if (!fs::is_regular_file(kit / "manifest.json") || !fs::is_directory(kit / "lib")) {
    std::fprintf(stderr,
                 "pt-grade: no grading kit at %s (build it with `cmake --build --preset default --target grader-kit`, "
                 "or pass --kit)\n",
                 kit.c_str());
    return 2;
  }
  // Read once, before any code under test is built or run.
  Manifest manifest = read_manifest((kit / "manifest.json").string());
  if (!opt.count_extensions) leave_extensions_uncounted(manifest);
  const Redactor redactor(manifest.solution_lines);
  const std::map<int, std::string> expected = task_file_names(kit);

  Report report;
  for (const auto& [part, tests] : manifest.parts)
    report.parts.push_back(pending_part(part, tests, "not graded yet: the grader stopped before this part"));
  auto part_index = [&](int part) {
    for (size_t i = 0; i < report.parts.size(); ++i)
      if (report.parts[i].part == part) return i;
    return report.parts.size();
  };
  HtmlReport page;
  page.title = fs::path(opt.path).filename().string();
  page.report = &report;
  page.handouts = index_handouts((kit / "handouts").string());
  page.renders_note = "No renders yet: the parts are graded first.";
  // Both reports are rewritten, whole and atomically, after every step.
  auto save = [&] {
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (!opt.json_path.empty()) write_results_json(opt.json_path, report);
    if (!opt.html_path.empty()) write_html_report(opt.html_path, page);
    if (!opt.prairielearn_path.empty()) write_prairielearn_json(opt.prairielearn_path, page);
  };
  auto set_part = [&](int part, const std::string& why) {
    const size_t i = part_index(part);
    if (i < report.parts.size()) report.parts[i] = pending_part(part, manifest.parts.at(part), why);
  };
  save();

  // 2. The files.
  const Submission sub = read_submission(opt.path, expected);
  for (const auto& n : sub.notes) report.notes.push_back(n);
  if (!sub.problems.empty()) {
    std::string why = "submission rejected before building:";
    for (const auto& p : sub.problems) why += "\n  " + p;
    // Said once, in the notes; each part's tests say its first lines.
    const std::string each = summary(why, "the whole list is in the report's notes");
    for (auto& p : report.parts) set_part(p.part, each);
    report.notes.push_back(why);
    report.ungradable = why;
    report.complete = true;
    save();
    print_report(report, false);
    return 0;
  }
  std::set<int> submitted;
  for (const auto& f : sub.files) submitted.insert(f.part);
  for (auto& p : report.parts)
    if (!submitted.count(p.part))
      set_part(p.part, "not submitted: no " + (expected.count(p.part) ? expected.at(p.part) : "task file") + " in the submission");

  // 3. What each file may include, and what an instructor should read.
  const std::set<std::string> headers = framework_headers(kit);
  std::vector<const TaskFile*> buildable;
  for (const auto& f : sub.files) {
    if (!manifest.parts.count(f.part)) {
      report.notes.push_back(f.where + ": part " + std::to_string(f.part) + " has no graded tests in this kit; not built");
      continue;
    }
    std::string flags;
    const std::string rejected = intake_rejection(f, headers, &flags);
    if (!flags.empty()) report.instructor_notes.push_back(flags);
    if (!rejected.empty()) {
      set_part(f.part, rejected);
      continue;
    }
    buildable.push_back(&f);
  }
  save();

  // Steps 4 to 6 work in a folder of the grader's own (work_area.h). An error
  // not foreseen still ends in a complete report saying what failed, and the
  // folder goes with its WorkArea on every path out.
  Graded graded{opt, kit, deadline, manifest, redactor, expected, buildable, report, page, save, set_part, part_index};
  try {
    return build_and_grade(graded);
  } catch (const std::exception& e) {
    report.notes.push_back(std::string("the grader failed (an instructor must look): ") + e.what());
    report.ungradable = "the grader failed; please tell your instructor";
    report.complete = true;
    save();
    print_report(report, false);
    std::fprintf(stderr, "pt-grade: %s\n", e.what());
    return 2;
  }
}

namespace {

int build_and_grade(Graded& graded) {
  auto& [opt, kit, deadline, manifest, redactor, expected, buildable, report, page, save, set_part, part_index] = graded;
  // 4. A fresh tree: the kit (no solution source) and the task files.
  const bool namespaces = opt.sandbox.confine && std::find(opt.sandbox.without.begin(), opt.sandbox.without.end(),
                                                           "namespaces") == opt.sandbox.without.end();
  WorkArea area(opt.work.empty() ? fs::temp_directory_path().string() : opt.work,
                opt.keep_work ? "--keep-work: a tmpfs would end with the grader"
                : namespaces  ? ""
                              : "left out (--no-sandbox or --sandbox-without namespaces)");
  if (opt.keep_work) area.keep();
  if (!area.unbounded_reason().empty())
    report.notes.push_back("no tmpfs bounds the submission's files (" + area.unbounded_reason() + "): the builds and " +
                           "renders are stopped when they pass " + std::to_string(kDiskBytes >> 20) +
                           " MiB, checked four times a second");
  const fs::path tree = area.tree();
  for (const char* item : {"CMakeLists.txt", "include", "lib", "src", "bin"})
    fs::copy(kit / item, tree / item, fs::copy_options::recursive);
  fs::create_directories(tree / "tasks");
  std::string parts_list;
  for (const TaskFile* f : buildable) {
    std::ofstream(tree / "tasks" / f->name, std::ios::binary) << f->text;
    parts_list += (parts_list.empty() ? "" : ";") + std::to_string(f->part);
  }

  std::map<int, std::string> binaries, workers;
  const bool landlock = opt.sandbox.confine && std::find(opt.sandbox.without.begin(), opt.sandbox.without.end(),
                                                         "landlock") == opt.sandbox.without.end();
  KitBuild kit_build(tree.string(), landlock);
  bool build_stopped = false;  // by the bound, where no tmpfs enforces it
  if (!area.unbounded_reason().empty())
    kit_build.stop_when([&area, &build_stopped] { return build_stopped = build_stopped || area.exceeded(); });
  if (!buildable.empty() && !kit_build.unconfined_reason().empty())
    report.notes.push_back("the build was not confined (" + kit_build.unconfined_reason() +
                           "): the compiler could read any file this grader can, e.g. with an assembler .incbin");
  if (!buildable.empty()) {
    std::string out;
    const int rc = kit_build.run({"cmake", "-S", tree.string(), "-B", (tree / "build").string(), "-G", "Ninja",
                                  "-DPT_PARTS_SUBMITTED=" + parts_list},
                                 120, &out);
    if (rc != 0) {
      std::fprintf(stderr, "pt-grade: the grading kit's build could not be configured:\n%s\n", capped(out, 4000).c_str());
      for (const TaskFile* f : buildable) set_part(f->part, "not built: the grading kit could not be configured (an instructor must look)");
      report.notes.push_back("cmake configure failed:\n" + out.substr(0, 4000));
      buildable.clear();
    }
  }
  if (!buildable.empty()) {
    // The header probe (no student code) first, on its own clock, so that
    // each part's build limit covers that part alone; a probe that does not
    // build leaves every part's dependency check to say so.
    std::string out;
    if (kit_build.run({"cmake", "--build", (tree / "build").string(), "--target", "pt_header_probe"}, 60, &out) != 0)
      report.notes.push_back("the kit's header probe did not build:\n" + out.substr(0, 4000));
  }
  for (const TaskFile* f : buildable) {
    const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
    if (left <= 1) {
      set_part(f->part, "not built: the submission's time budget ran out");
      continue;
    }
    // A part across the process boundary (boundary/README.md): the build makes
    // only its worker; the verifier is the kit's, outside the tree.
    const fs::path verifier = kit / "verifiers" / ("part" + std::to_string(f->part) + "_verify");
    const bool across = fs::is_regular_file(verifier) &&
                        fs::is_regular_file(tree / "lib" / ("libpt_boundary_worker_part" + std::to_string(f->part) + ".a"));
    const std::string target = "part" + std::to_string(f->part) + (across ? "_worker" : "_tests");
    std::string out;
    const auto build_start = Clock::now();
    build_stopped = false;
    const int rc = kit_build.run({"cmake", "--build", (tree / "build").string(), "--target", target},
                                 std::min(opt.build_seconds, left), &out);
    const double took = std::chrono::duration<double>(Clock::now() - build_start).count();
    if (rc != 0) {
      const bool timed_out = rc == 124 || rc == 137;
      std::string why = timed_out ? f->where + " did not build within " + seconds_text(opt.build_seconds) + ":\n"
                                  : f->where + " does not build: part " + std::to_string(f->part) + " scores 0.\n";
      if (const std::string bound = disk_bound_note(out, area, build_stopped); !bound.empty()) why += bound + ".\n";
      why += compiler_errors(out, tree.string());
      // The compiler quotes the lines it complains about, and `#line` can make
      // it quote any file it reads: redacted like a test's message.
      if (const size_t redacted = redactor.redact(why); redacted > 0)
        report.notes.push_back("part " + std::to_string(f->part) + ": " + std::to_string(redacted) +
                               " line(s) of the solution were removed from the build's messages (read its task file)");
      set_part(f->part, why);
      continue;
    }
    // The task file, the framework's headers, the compiler's own (intrinsics,
    // <stddef.h>), and what the header probe opened: the standard library and GLM.
    const auto unexpected = unexpected_dependencies(
        (tree / "build").string(), "student_part" + std::to_string(f->part) + ".dir/",
        {(tree / "tasks").string() + "/", (tree / "include").string() + "/", "/usr/lib/gcc/"}, "pt_header_probe.dir/");
    if (!unexpected.empty()) {
      std::string why = "while compiling " + f->where + " the compiler read files outside the framework's headers and "
                        "the standard library: rejected.\n";
      why += capped_list(unexpected, 50, 512);
      set_part(f->part, why);
      continue;
    }
    report.notes.push_back("part " + std::to_string(f->part) + ": built in " + seconds_text(std::round(took * 10) / 10));
    if (across) {
      binaries[f->part] = verifier.string();
      workers[f->part] = (tree / "build" / target).string();
    } else {
      binaries[f->part] = (tree / "build" / target).string();
    }
  }
  save();

  // 5. Grading, in the sandbox.
  if (!binaries.empty()) {
    SandboxOptions sandbox_options = opt.sandbox;
    sandbox_options.readable.push_back((kit / "scenes").string());
    Sandbox sandbox(sandbox_options);
    report.sandbox_layers = sandbox.layers();
    report.sandbox_missing = sandbox.layers_missing();
    report.sandbox_ids = sandbox.layer_ids();
    for (const auto& m : sandbox.layers_missing()) report.notes.push_back("sandbox layer missing: " + m);
    GradeLimits limits = opt.limits;
    limits.deadline = deadline;
    // A run's own folder, made where the sandbox can plant nothing: for a
    // failing image test's images (test_images.h) and for each render.
    ImageFolders image_folders{[&area](std::string* error) { return area.fresh_render_folder(error); },
                               [&opt](const std::string& dir) {
                                 std::error_code ec;
                                 if (!opt.keep_work) fs::remove_all(dir, ec);
                               }};
    for (const auto& [part, binary] : binaries) {
      const auto worker = workers.find(part);
      // The log beside what was built from the submission (a verifier is the kit's, shared).
      const std::string log = (worker != workers.end() ? worker->second : binary) + ".grade.log";
      report.parts[part_index(part)] = grade_binary(part, binary, manifest.parts.at(part), limits, sandbox, log, redactor,
                                                    worker != workers.end() ? worker->second : "",
                                                    opt.html_path.empty() ? nullptr : &image_folders);
      save();  // every process of that run is dead by now
    }
    if (opt.leaderboard) {
      add_leaderboard(report, kit.string(), binaries, workers, sandbox, deadline);
      save();
    }
    // 6. The renders of the report.
    if (opt.renders && (!opt.html_path.empty() || !opt.prairielearn_path.empty())) {
      RenderJob job;
      job.kit = kit.string();
      job.tree = tree.string();
      job.configure_parts = parts_list;
      for (const auto& p : report.parts) {
        job.part_names[p.part] =
            "part " + std::to_string(p.part) + (expected.count(p.part) ? " (tasks/" + expected.at(p.part) + ")" : "");
        if (binaries.count(p.part) && p.earned() > 0) job.student_parts.insert(p.part);
      }
      job.seconds = std::min(opt.render_seconds, std::chrono::duration<double>(deadline - Clock::now()).count());
      job.build_seconds = opt.build_seconds;
      job.fresh_folder = image_folders.fresh;
      job.discard_folder = image_folders.discard;
      if (!area.unbounded_reason().empty()) job.over_bound = [&area] { return area.exceeded(); };
      job.bound_note = [&area](const std::string& output, bool stopped) {
        return disk_bound_note(output, area, stopped);
      };
      if (job.seconds < 5) {
        page.renders_note = "No renders: the submission's time budget ran out.";
      } else {
        page.renders_note = "Rendering the scene library...";
        save();
        // The renderer is built from the same hostile task files: confined the same way.
        auto build = [&](const std::vector<std::string>& argv, double seconds, std::string* output) {
          return kit_build.run(argv, seconds, output);
        };
        render_library(job, build, sandbox, page, &report.notes);
      }
    } else {
      page.renders_note = "No renders: turned off (--no-renders).";
    }
  } else {
    page.renders_note = "No renders: no part of the submission built.";
  }
  report.complete = true;
  save();
  print_report(report, false);
  if (opt.keep_work) std::printf("build tree and renders kept: %s\n", area.root().c_str());
  return 0;
}

}  // namespace

}  // namespace pt::grade
