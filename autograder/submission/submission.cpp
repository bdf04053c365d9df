#include "submission/submission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>

#include "compile/dependency_check.h"
#include "compile/kit_build.h"
#include "compile/work_area.h"
#include "report/html_report.h"
#include "report/leaderboard.h"
#include "report/prairielearn_report.h"
#include "report/redact.h"
#include "report/report.h"
#include "report/report_renders.h"
#include "report/report_text.h"
#include "run/manifest.h"
#include "submission/pipeline.h"

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

bool layer_wanted(const SandboxOptions& sandbox, const char* layer) {
  return sandbox.confine && std::find(sandbox.without.begin(), sandbox.without.end(), layer) == sandbox.without.end();
}

// The grader's ending: results.json (Gradescope's), report.html and
// PrairieLearn's results, every part 0 of its maximum until it is graded,
// rewritten whole and atomically after every stage.
class Reports : public Ending {
 public:
  Reports(const SubmissionOptions& opt, const Manifest& manifest, const fs::path& kit)
      : opt_(opt), manifest_(manifest), start_(Clock::now()) {
    for (const auto& [part, tests] : manifest.parts)
      report.parts.push_back(pending_part(part, tests, "not graded yet: the grader stopped before this part"));
    page.title = fs::path(opt.path).filename().string();
    page.report = &report;
    page.handouts = index_handouts((kit / "handouts").string());
    page.renders_note = "No renders yet: the parts are graded first.";
  }

  void save() {
    report.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    if (!opt_.json_path.empty()) write_results_json(opt_.json_path, report);
    if (!opt_.html_path.empty()) write_html_report(opt_.html_path, page);
    if (!opt_.prairielearn_path.empty()) write_prairielearn_json(opt_.prairielearn_path, page);
  }
  void set_part(int n, const std::string& why) {
    for (auto& p : report.parts)  // the manifest's parts
      if (p.part == n) p = pending_part(n, manifest_.parts.at(n), why);
  }

  void refused(const TaskFile& file, Stage stage, const std::string& why) override {
    if (stage == Stage::Files)
      report.notes.push_back(file.where + ": " + why);
    else
      set_part(file.part, why);
  }
  void built(const TaskFile& file, double seconds) override {
    report.notes.push_back("part " + std::to_string(file.part) + ": built in " +
                           number(std::round(seconds * 10) / 10, "%g s"));
  }

  void finish() {
    report.complete = true;
    save();
    print_report(report, false);
  }

  Report report;
  HtmlReport page;

 private:
  const SubmissionOptions& opt_;
  const Manifest& manifest_;
  Clock::time_point start_;
};

// Stage 3 for the grader: a fresh tree of the kit (no solution source: the
// solution is prebuilt) with the task files, configured once, each part then
// built there on its own, confined (compile/kit_build.h), within its limit
// and the submission's budget.
class KitTree : public PartBuilder {
 public:
  KitTree(const SubmissionOptions& opt, const fs::path& kit, WorkArea& area, Clock::time_point deadline,
          const Redactor& redactor, std::vector<std::string>& notes)
      : opt_(opt), kit_(kit), tree_(area.tree()), area_(area), deadline_(deadline), redactor_(redactor),
        notes_(notes) {}

  // Copies the kit and the files, configures the tree and builds the header
  // probe. A tree that does not configure leaves every part unbuilt, saying so.
  void prepare(const std::vector<const TaskFile*>& files) {
    for (const char* item : {"CMakeLists.txt", "include", "lib", "src", "bin"})
      fs::copy(kit_ / item, tree_ / item, fs::copy_options::recursive);
    fs::create_directories(tree_ / "tasks");
    for (const TaskFile* f : files) {
      std::ofstream(tree_ / "tasks" / f->name, std::ios::binary) << f->text;
      parts_ += (parts_.empty() ? "" : ";") + std::to_string(f->part);
    }
    // Confined once the tree is whole: Landlock's rules name its folders.
    build_.emplace(tree_.string(), layer_wanted(opt_.sandbox, "landlock"));
    if (!area_.unbounded_reason().empty())
      build_->stop_when([this] { return stopped_ = stopped_ || area_.exceeded(); });
    if (files.empty()) return;
    if (!build_->unconfined_reason().empty())
      notes_.push_back("the build was not confined (" + build_->unconfined_reason() +
                       "): the compiler could read any file this grader can, e.g. with an assembler .incbin");
    std::string out;
    if (build_->run({"cmake", "-S", tree_.string(), "-B", (tree_ / "build").string(), "-G", "Ninja",
                    "-DPT_PARTS_SUBMITTED=" + parts_},
                   120, &out) != 0) {
      std::fprintf(stderr, "pt-grade: the grading kit's build could not be configured:\n%s\n", capped(out, 4000).c_str());
      notes_.push_back("cmake configure failed:\n" + out.substr(0, 4000));
      unconfigured_ = true;
      return;
    }
    // The header probe (no student code) first, on its own clock, so that
    // each part's build limit covers that part alone; a probe that does not
    // build leaves every part's dependency check to say so.
    if (build_->run({"cmake", "--build", (tree_ / "build").string(), "--target", "pt_header_probe"}, 60, &out) != 0)
      notes_.push_back("the kit's header probe did not build:\n" + out.substr(0, 4000));
  }

  std::string build(const TaskFile& f, BuiltPart* built) override {
    if (unconfigured_) return "not built: the grading kit could not be configured (an instructor must look)";
    const double left = std::chrono::duration<double>(deadline_ - Clock::now()).count();
    if (left <= 1) return "not built: the submission's time budget ran out";
    // A part across the process boundary (boundary/README.md): the build makes
    // only its worker; the verifier is the kit's, outside the tree.
    const std::string part = "part" + std::to_string(f.part);
    const fs::path verifier = kit_ / "verifiers" / (part + "_verify");
    const bool across = fs::is_regular_file(verifier) &&
                        fs::is_regular_file(tree_ / "lib" / ("libpt_boundary_worker_" + part + ".a"));
    const std::string target = part + (across ? "_worker" : "_tests");
    std::string out;
    stopped_ = false;
    const int rc = build_->run({"cmake", "--build", (tree_ / "build").string(), "--target", target},
                               std::min(opt_.build_seconds, left), &out);
    if (rc != 0) return failure(f, rc, out);
    built->binary = across ? verifier.string() : (tree_ / "build" / target).string();
    if (across) built->worker = (tree_ / "build" / target).string();
    return "";
  }

  // The task file, the framework's headers, the compiler's own (intrinsics,
  // <stddef.h>), and what the header probe opened: the standard library and GLM.
  std::vector<std::string> unexpected_reads(const TaskFile& f) override {
    return unexpected_dependencies((tree_ / "build").string(), "student_part" + std::to_string(f.part) + ".dir/",
                                   {(tree_ / "tasks").string() + "/", (tree_ / "include").string() + "/", "/usr/lib/gcc/"},
                                   "pt_header_probe.dir/");
  }

  const std::string& configured_parts() const { return parts_; }
  const fs::path& tree() const { return tree_; }
  KitBuild& kit_build() { return *build_; }

 private:
  std::string failure(const TaskFile& f, int rc, const std::string& out) {
    const bool timed_out = rc == 124 || rc == 137;
    std::string why = timed_out ? f.where + " did not build within " + number(opt_.build_seconds, "%g s") + ":\n"
                                : f.where + " does not build: part " + std::to_string(f.part) + " scores 0.\n";
    if (const std::string bound = disk_bound_note(out, area_, stopped_); !bound.empty()) why += bound + ".\n";
    why += compiler_errors(out, tree_.string());
    // The compiler quotes the lines it complains about, and `#line` can make
    // it quote any file it reads: redacted like a test's message.
    if (const size_t redacted = redactor_.redact(why); redacted > 0)
      notes_.push_back("part " + std::to_string(f.part) + ": " + std::to_string(redacted) +
                       " line(s) of the solution were removed from the build's messages (read its task file)");
    return why;
  }

  const SubmissionOptions& opt_;
  const fs::path kit_, tree_;
  WorkArea& area_;
  const Clock::time_point deadline_;
  const Redactor& redactor_;
  std::vector<std::string>& notes_;
  std::optional<KitBuild> build_;
  bool stopped_ = false;  // by the bound, where no tmpfs enforces it
  bool unconfigured_ = false;
  std::string parts_;  // PT_PARTS_SUBMITTED
};

// What stages 3 and 4 need besides the pipeline.
struct Grading {
  const SubmissionOptions& opt;
  const fs::path& kit;
  Clock::time_point deadline;
  const Manifest& manifest;
  const Redactor& redactor;
};

// The report's renders (report_renders.h), built and run like the parts.
void render(const Grading& g, const Pipeline& pipeline, KitTree& tree, WorkArea& area, const ImageFolders& folders,
            Sandbox& sandbox, Reports& out) {
  RenderJob job;
  job.kit = g.kit.string();
  job.tree = tree.tree().string();
  job.configure_parts = tree.configured_parts();
  for (const auto& p : out.report.parts) {
    const auto name = pipeline.expected().find(p.part);
    job.part_names[p.part] =
        "part " + std::to_string(p.part) + (name != pipeline.expected().end() ? " (tasks/" + name->second + ")" : "");
    if (pipeline.built().count(p.part) && p.earned() > 0) job.student_parts.insert(p.part);
  }
  job.seconds = std::min(g.opt.render_seconds, std::chrono::duration<double>(g.deadline - Clock::now()).count());
  job.build_seconds = g.opt.build_seconds;
  job.folders = folders;
  if (!area.unbounded_reason().empty()) job.over_bound = [&area] { return area.exceeded(); };
  job.bound_note = [&area](const std::string& output, bool stopped) { return disk_bound_note(output, area, stopped); };
  if (job.seconds < 5) {
    out.page.renders_note = "No renders: the submission's time budget ran out.";
    return;
  }
  out.page.renders_note = "Rendering the scene library...";
  out.save();
  // The renderer is built from the same hostile task files: confined the same way.
  auto build = [&tree](const std::vector<std::string>& argv, double seconds, std::string* output) {
    return tree.kit_build().run(argv, seconds, output);
  };
  render_library(job, build, sandbox, out.page, &out.report.notes);
}

// Stage 4 for every part built, then the leaderboard and the renders.
void grade_built(const Grading& g, Pipeline& pipeline, KitTree& tree, WorkArea& area, Reports& out) {
  SandboxOptions sandbox_options = g.opt.sandbox;
  sandbox_options.readable.push_back((g.kit / "scenes").string());
  Sandbox sandbox(sandbox_options);
  out.report.sandbox_layers = sandbox.layers();
  out.report.sandbox_missing = sandbox.layers_missing();
  out.report.sandbox_ids = sandbox.layer_ids();
  for (const auto& m : sandbox.layers_missing()) out.report.notes.push_back("sandbox layer missing: " + m);
  GradeLimits limits = g.opt.limits;
  limits.deadline = g.deadline;
  // A run's own folder, made where the sandbox can plant nothing: for a
  // failing image test's images (test_images.h) and for each render.
  const bool keep = g.opt.keep_work;
  const ImageFolders folders{[&area](std::string* error) { return area.fresh_render_folder(error); },
                             [keep](const std::string& dir) {
                               std::error_code ec;
                               if (!keep) fs::remove_all(dir, ec);
                             }};
  // Saved after each part: every process of its run is dead by then.
  pipeline.grade(g.manifest, limits, sandbox, g.redactor, g.opt.html_path.empty() ? nullptr : &folders, out.report,
                 [&out] { out.save(); });
  if (g.opt.leaderboard) {
    const auto two = pipeline.built().find(2);
    const BuiltPart part2 = two != pipeline.built().end() ? two->second : BuiltPart{};
    add_leaderboard(out.report, g.kit.string(), part2.binary, part2.worker, sandbox, g.deadline);
    out.save();
  }
  if (g.opt.renders && (!g.opt.html_path.empty() || !g.opt.prairielearn_path.empty()))
    render(g, pipeline, tree, area, folders, sandbox, out);
  else
    out.page.renders_note = "No renders: turned off (--no-renders).";
}

// Stages 3 and 4 work in a folder of the grader's own (work_area.h), which
// goes with its WorkArea on every path out.
int build_and_grade(const Grading& g, Pipeline& pipeline, Reports& out) {
  const bool namespaces = layer_wanted(g.opt.sandbox, "namespaces");
  WorkArea area(g.opt.work.empty() ? fs::temp_directory_path().string() : g.opt.work,
                g.opt.keep_work ? "--keep-work: a tmpfs would end with the grader"
                : namespaces    ? ""
                                : "left out (--no-sandbox or --sandbox-without namespaces)");
  if (g.opt.keep_work) area.keep();
  if (!area.unbounded_reason().empty())
    out.report.notes.push_back("no tmpfs bounds the submission's files (" + area.unbounded_reason() +
                               "): the builds and renders are stopped when they pass " +
                               std::to_string(kDiskBytes >> 20) + " MiB, checked four times a second");
  KitTree tree(g.opt, g.kit, area, g.deadline, g.redactor, out.report.notes);
  tree.prepare(pipeline.buildable());
  pipeline.build(tree);
  out.save();
  if (pipeline.built().empty())
    out.page.renders_note = "No renders: no part of the submission built.";
  else
    grade_built(g, pipeline, tree, area, out);
  out.finish();
  if (g.opt.keep_work) std::printf("build tree and renders kept: %s\n", area.root().c_str());
  return 0;
}

}  // namespace

int grade_submission(const SubmissionOptions& opt) {
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(opt.budget_seconds));
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
  Reports out(opt, manifest, kit);
  out.save();

  std::set<int> graded;
  for (const auto& [part, tests] : manifest.parts) graded.insert(part);
  Pipeline pipeline(task_file_names(kit), graded, out);
  // 1. The files.
  const bool taken = pipeline.take_files(opt.path);
  const Submission& sub = pipeline.submission();
  for (const auto& n : sub.notes) out.report.notes.push_back(n);
  if (!taken) {
    const std::string why = pipeline.rejection();
    // Said once, in the notes; each part's tests say its first lines.
    for (auto& p : out.report.parts) out.set_part(p.part, summary(why, "the whole list is in the report's notes"));
    out.report.ungradable = why;
    out.report.notes.push_back(why);
    out.finish();
    return 0;
  }
  for (const auto& p : out.report.parts)
    if (const std::string why = pipeline.why_not_graded(p.part); !why.empty()) out.set_part(p.part, why);
  // 2. The directives that read a file as data.
  pipeline.check_directives();
  out.save();

  // An error not foreseen still ends in a complete report saying what failed.
  try {
    return build_and_grade({opt, kit, deadline, manifest, redactor}, pipeline, out);
  } catch (const std::exception& e) {
    out.report.notes.push_back(std::string("the grader failed (an instructor must look): ") + e.what());
    out.report.ungradable = "the grader failed; please tell your instructor";
    out.finish();
    std::fprintf(stderr, "pt-grade: %s\n", e.what());
    return 2;
  }
}

}  // namespace pt::grade
