#include "submission/pipeline.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "report/report_text.h"
#include "intake/file_directives.h"

namespace pt::grade {

namespace {

// A submission decides how many findings there are (a million refused lines):
// the first ones are listed, each capped, then how many more there are.
std::string joined_findings(const std::vector<FileDirective>& found, const std::string& file) {
  std::vector<std::string> lines;
  for (const auto& f : found) lines.push_back(file + ":" + std::to_string(f.line) + ": " + f.what);
  return capped_list(lines, 100, 512);
}

// Stage 2 for one task file: "" when it may be built, else why not (the
// report's text).
std::string intake_rejection(const TaskFile& f) {
  if (f.too_large)
    return f.where + " is larger than " + std::to_string(kMaxTaskFileBytes >> 20) + " MiB: rejected before building";
  const auto found = file_directives(f.text);
  if (!found.empty()) return f.where + " rejected before building:\n" + joined_findings(found, f.where);
  return "";
}

}  // namespace

// The compiler's errors first (with the lines that locate them), ninja's
// progress lines dropped.
std::string compiler_errors(const std::string& output, const std::string& tree_dir) {
  const size_t max_lines = 40;
  std::istringstream in(output);
  std::vector<std::string> kept;
  const std::string prefix = tree_dir + "/";
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

Pipeline::Pipeline(std::map<int, std::string> expected, std::set<int> graded, Ending& ending)
    : expected_(std::move(expected)), graded_(std::move(graded)), ending_(ending) {}

bool Pipeline::take_files(const std::string& path) {
  submission_ = read_submission(path, expected_);
  return submission_.problems.empty();
}

std::string Pipeline::rejection() const {
  std::string why = "submission rejected before building:";
  for (const auto& p : submission_.problems) why += "\n  " + p;
  return why;
}

std::string Pipeline::why_not_graded(int part) const {
  if (const auto it = refused_.find(part); it != refused_.end()) return it->second;
  for (const auto& f : submission_.files)
    if (f.part == part) return "";
  const auto name = expected_.find(part);
  return "not submitted: no " + (name != expected_.end() ? name->second : std::string("task file")) +
         " in the submission";
}

void Pipeline::refuse(const TaskFile& file, Stage stage, const std::string& why) {
  if (stage != Stage::Files) refused_[file.part] = why;
  ending_.refused(file, stage, why);
}

void Pipeline::check_directives() {
  for (const auto& f : submission_.files) {
    if (!graded_.count(f.part)) {
      refuse(f, Stage::Files, "part " + std::to_string(f.part) + " has no graded tests in this kit; not built");
      continue;
    }
    if (const std::string rejected = intake_rejection(f); !rejected.empty()) {
      refuse(f, Stage::Directives, rejected);
      continue;
    }
    ending_.accepted(f);
    buildable_.push_back(&f);
  }
}

void Pipeline::build(PartBuilder& builder) {
  for (const TaskFile* f : buildable_) {
    BuiltPart part;
    const auto start = std::chrono::steady_clock::now();
    if (const std::string why = builder.build(*f, &part); !why.empty()) {
      refuse(*f, Stage::Build, why);
      continue;
    }
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (const auto reads = builder.unexpected_reads(*f); !reads.empty()) {
      refuse(*f, Stage::Reads,
                      "while compiling " + f->where + " the compiler read files outside the framework's headers and "
                      "the standard library: rejected.\n" + capped_list(reads, 50, 512));
      continue;
    }
    built_[f->part] = part;
    ending_.built(*f, took);
  }
}

void Pipeline::grade(const Manifest& manifest, const GradeLimits& limits, Sandbox& sandbox, const Redactor& redactor,
                     const ImageFolders* images, Report& report, const std::function<void()>& after_each) const {
  for (const auto& [part, tests] : manifest.parts) {
    const auto slot = std::find_if(report.parts.begin(), report.parts.end(), [part = part](auto& p) { return p.part == part; });
    PartResult& result = slot != report.parts.end() ? *slot : report.parts.emplace_back();
    const auto b = built_.find(part);
    if (b == built_.end()) {
      const std::string why = why_not_graded(part);
      result = pending_part(part, tests, why.empty() ? "not built" : why);
      continue;
    }
    // The log beside what was built from the task file (a verifier is shared).
    const std::string log = (b->second.worker.empty() ? b->second.binary : b->second.worker) + ".grade.log";
    result = grade_binary(part, b->second.binary, tests, limits, sandbox, log, redactor, b->second.worker, images);
    if (after_each) after_each();
  }
}

}  // namespace pt::grade
