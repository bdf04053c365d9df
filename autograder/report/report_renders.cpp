#include "report/report_renders.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>

#include <nlohmann/json.hpp>

#include "process/command.h"
#include "report/report_text.h"

namespace pt::grade {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The render's time limit, and the disk bound where no tmpfs enforces it:
// asked at least every 200 ms while the render runs.
class RenderWatch : public RunObserver {
 public:
  RenderWatch(Clock::time_point end, double limit, const std::function<bool()>& over)
      : end_(end), limit_(limit), over_(over) {}
  void on_channel(std::string_view) override {}
  Deadline deadline() const override {
    if (over_ && over_()) stopped_ = true;
    return {stopped_ ? Clock::now() : end_, limit_};
  }
  bool stopped_by_bound() const { return stopped_; }

 private:
  Clock::time_point end_;
  double limit_;
  std::function<bool()> over_;
  mutable bool stopped_ = false;
};

double seconds_until(Clock::time_point t) { return std::chrono::duration<double>(t - Clock::now()).count(); }

struct SceneRender {
  std::string name, purpose, settings, exr;
  int samples = 0;
  std::vector<std::string> arguments;
};

RenderComparison comparison_of(const SceneRender& s) {
  RenderComparison c;
  c.scene = s.name;
  c.purpose = s.purpose;
  c.settings = s.settings;
  return c;
}

// One render of one scene by `renderer` in the sandbox, judged by the kit's
// pt-library-check into `checked` (a folder the sandbox cannot write).
RenderComparison render_and_check(const RenderJob& job, const SceneRender& s, const fs::path& renderer,
                                  const fs::path& checked, Sandbox& sandbox, Clock::time_point end) {
  RenderComparison c = comparison_of(s);
  std::string error;
  const fs::path out = job.folders.fresh(&error);
  if (out.empty()) {
    c.error = "not rendered: " + error + " (an instructor must look)";
    return c;
  }
  struct Discard {  // the EXR is judged, and its PNGs drawn elsewhere: the folder goes
    const RenderJob& job;
    const fs::path& out;
    ~Discard() { job.folders.discard(out.string()); }
  } discard{job, out};
  // Each render gets at most a third of what is left, and 20 s: a renderer
  // that hangs on the first scene leaves time for the others.
  const double limit = std::max(1.0, std::min(20.0, seconds_until(end) / 3));
  RunRequest req;
  req.binary = renderer.string();
  req.args = s.arguments;
  // Output paths point into `out`, where this run may write.
  const fs::path exr = out / fs::path(s.exr).filename();
  for (auto& a : req.args)
    if (a.rfind(fs::path(s.exr).parent_path().string(), 0) == 0) a = (out / fs::path(a).filename()).string();
  req.args.insert(req.args.end(), {"-t", "1"});  // one thread: the sandbox counts processes, and the page times nothing
  req.output_dir = out.string();
  RenderWatch watch(Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit)),
                    limit, job.over_bound);
  const RunOutcome run = sandbox.run(req, watch);
  const std::string bound = job.bound_note(run.output, watch.stopped_by_bound());
  if (!run.exit.exited_ok()) {
    std::string tail = run.output.size() > 400 ? "..." + run.output.substr(run.output.size() - 400) : run.output;
    c.error = (bound.empty() ? "" : bound + ": ") + "the renderer " +
              (watch.stopped_by_bound() ? std::string("was stopped") : run.exit.describe()) +
              (tail.empty() ? "" : ":\n" + tail);
    return c;
  }
  // The run is over and every process of it dead: nothing can swap the file
  // after this check. A link could point the trusted reader anywhere.
  if (!fs::is_regular_file(fs::symlink_status(exr))) {
    c.error = (bound.empty() ? "" : bound + ": ") + "the renderer exited normally but left no EXR at " +
              exr.filename().string();
    return c;
  }
  fs::create_directories(checked);
  std::string answer;
  const int rc = run_command({(fs::path(job.kit) / "bin" / "pt-library-check").string(), "compare", "--library",
                              (fs::path(job.kit) / "scenes" / "library.json").string(), "--scene", s.name, "--render",
                              exr.string(), "--samples", std::to_string(s.samples), "--out", checked.string()},
                             &answer);
  const json j = json::parse(answer, nullptr, false);
  if (!j.is_object()) {
    c.error = "pt-library-check failed (exit status " + std::to_string(rc) + "): an instructor must look";
    return c;
  }
  if (j.contains("error")) {
    c.error = "its image is unusable: " + j["error"].get<std::string>();
    return c;
  }
  c.relmse = j["relmse"].get<double>();
  c.expected_relmse = j["expected_relmse"].get<double>();
  c.bound = j["bound"].get<double>();
  c.flagged = !j["passed"].get<bool>();
  c.detail = j["explanation"].get<std::string>();
  c.difference_scale = j["difference_scale"].get<double>();
  c.student_png = j["submission_png"].get<std::string>();
  c.reference_png = j["reference_png"].get<std::string>();
  c.difference_png = j["difference_png"].get<std::string>();
  return c;
}

}  // namespace

void render_library(const RenderJob& job, const BuildRunner& build, Sandbox& sandbox, HtmlReport& page,
                    std::vector<std::string>* notes) {
  const auto start = Clock::now();
  const auto end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(job.seconds));
  if (job.student_parts.empty()) {
    page.renders_note = "No part of the submission earned a point, so its renders would show only the solution: none made.";
    return;
  }
  const fs::path tree(job.tree);
  const std::string parts = joined(job.student_parts, ";");

  // The renderers: configured with the parts that earned points.
  std::string out;
  int rc = build({"cmake", "-S", tree.string(), "-B", (tree / "build").string(),
                  "-DPT_PARTS_SUBMITTED=" + job.configure_parts, "-DPT_RENDER_STUDENT_PARTS=" + parts},
                 std::max(1.0, seconds_until(end)), &out);
  if (rc == 0)
    rc = build({"cmake", "--build", (tree / "build").string(), "--target", "pathtracer"},
               std::max(1.0, std::min(job.build_seconds, seconds_until(end))), &out);
  if (rc != 0) {
    page.renders_note = "No renders: the renderer with part(s) " + joined(job.student_parts, ", ") +
                        " of the submission did not build (an instructor must look).";
    notes->push_back("renderer build failed:\n" + out.substr(0, 4000));
    return;
  }

  // What to render: the kit's trusted plan.
  // (Its output paths are rewritten into each render's own folder.)
  std::string plan_text;
  run_command({(fs::path(job.kit) / "bin" / "pt-library-check").string(), "plan", "--library",
               (fs::path(job.kit) / "scenes" / "library.json").string(), "--out", (tree / "plan").string()},
              &plan_text);
  std::vector<SceneRender> scenes;
  try {
    for (const auto& e : json::parse(plan_text))
      scenes.push_back({e["name"], e["purpose"], e["settings"], e["exr"], e["samples"].get<int>(),
                        e["arguments"].get<std::vector<std::string>>()});
  } catch (const json::exception& e) {
    page.renders_note = "No renders: the kit's scene library could not be read (an instructor must look).";
    notes->push_back(std::string("pt-library-check plan: ") + e.what());
    return;
  }

  // Which renders are wrong: flagged by the check, or failed (a crash, a
  // missing image); not those the budget left unmade.
  std::vector<size_t> wrong;
  for (const auto& s : scenes) {
    RenderComparison c = comparison_of(s);
    if (seconds_until(end) < 2) {
      c.error = "not rendered: the report's render budget (" + std::to_string(int(job.seconds)) + " s) ran out";
    } else {
      c = render_and_check(job, s, tree / "build" / "pathtracer", tree / "checked", sandbox, end);
      c.student_parts.assign(job.student_parts.begin(), job.student_parts.end());
      if (c.flagged || !c.error.empty()) wrong.push_back(page.renders.size());
    }
    page.renders.push_back(c);
  }

  // Which part a wrong image points at.
  std::vector<RenderComparison*> flagged;
  for (size_t i : wrong) flagged.push_back(&page.renders[i]);
  if (!flagged.empty() && job.student_parts.size() == 1) {
    for (auto* c : flagged) c->suspect = job.part_names.at(*job.student_parts.begin());
  } else if (!flagged.empty()) {
    std::map<std::string, std::vector<int>> alone;  // scene -> parts whose image is wrong by themselves
    std::set<int> tried;
    for (int m : job.student_parts) {
      if (seconds_until(end) < 4) break;
      const std::string target = "pathtracer_part" + std::to_string(m);
      if (build({"cmake", "--build", (tree / "build").string(), "--target", target},
                std::max(1.0, std::min(job.build_seconds, seconds_until(end))), &out) != 0)
        continue;
      tried.insert(m);
      for (auto* c : flagged) {
        if (seconds_until(end) < 2) break;
        for (const auto& s : scenes)
          if (s.name == c->scene) {
            const RenderComparison one = render_and_check(job, s, tree / "build" / target,
                                                          tree / "checked" / ("part" + std::to_string(m)), sandbox, end);
            if (one.flagged || !one.error.empty()) alone[c->scene].push_back(m);
          }
      }
    }
    for (auto* c : flagged) {
      const auto& parts_alone = alone[c->scene];
      if (!parts_alone.empty()) {
        for (int m : parts_alone) c->suspect += (c->suspect.empty() ? "" : " and ") + job.part_names.at(m);
      } else if (tried.size() == job.student_parts.size()) {
        c->suspect = "the parts together (each alone, with the solution for the rest, renders within the noise)";
      } else {
        c->suspect = "one of part(s) " + joined(job.student_parts, ", ") + " (the time ran out before each was tried alone)";
      }
    }
  }
  page.renders_note = "Rendered with the submission's part(s) " + joined(job.student_parts, ", ") +
                      " (those that earned points) and the solution for the rest, in the sandbox, at the library "
                      "test's sample count and seed; judged by the library test's own check (false-alarm "
                      "probability 1e-5 per image). Renders and builds took " +
                      number(std::chrono::duration<double>(Clock::now() - start).count(), "%.1f s") +
                      ". The renders do not change the score.";
}

}  // namespace pt::grade
