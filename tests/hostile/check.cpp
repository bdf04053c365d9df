// pt-hostile-check: grades one hostile case with the command given after
// `--` and checks that the results.json it wrote is honest (README.md).
//
//   pt-hostile-check --case DIR --manifest FILE --results FILE --source-dir DIR
//                    --pt-grade PT_GRADE [--fallback] -- GRADING COMMAND...
//
// --fallback: the command leaves sandbox layers out (expect.json's
// "fallback"), and the case needs the layers that "fallback" lists instead.
//
// Honest means: the grader survived; every graded test of the part is listed
// with the manifest's points (the maximum never shrinks); the tests of the
// case's lost_tasks scored 0 with a message matching its failure pattern and
// every other test scored full marks; the total is their sum; the file does
// not change after the grader has finished; and no line of a reference file
// appears in it. Exit status 0 honest, 1 not, 77 skipped (a sandbox layer the
// case needs is missing here), 2 could not check.
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.h"

namespace {

using nlohmann::json;
using pt::grade::run_command;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Lines of a solution file worth looking for: long enough to be code, not a
// brace or a common include.
std::vector<std::string> telling_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto b = line.find_first_not_of(" \t"), e = line.find_last_not_of(" \t\r");
    if (b == std::string::npos) continue;
    line = line.substr(b, e - b + 1);
    if (line.size() >= 24 && line.rfind("#include", 0) != 0) lines.push_back(line);
  }
  return lines;
}

// The binary a `--binary N=FILE` argument names.
std::string binary_graded(const std::vector<std::string>& command) {
  for (size_t i = 0; i + 1 < command.size(); ++i)
    if (command[i] == "--binary") return command[i + 1].substr(command[i + 1].find('=') + 1);
  return "";
}

// Processes running `binary` now.
int survivors(const std::string& binary) {
  int n = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
    const std::string cmdline = read_file(entry.path().string() + "/cmdline");
    n += !cmdline.empty() && cmdline.c_str() == binary;
  }
  return n;
}

struct Checker {
  std::vector<std::string> failures;
  void expect(bool ok, const std::string& what) {
    if (!ok) failures.push_back(what);
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::string case_dir, manifest_path, results_path, source_dir, pt_grade;
  std::vector<std::string> command;
  bool fallback = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 < argc) out = argv[++i];
    };
    if (a == "--case") value(case_dir);
    else if (a == "--manifest") value(manifest_path);
    else if (a == "--results") value(results_path);
    else if (a == "--source-dir") value(source_dir);
    else if (a == "--pt-grade") value(pt_grade);
    else if (a == "--fallback") fallback = true;
    else if (a == "--") {
      command.assign(argv + i + 1, argv + argc);
      break;
    }
  }
  if (case_dir.empty() || manifest_path.empty() || results_path.empty() || command.empty()) {
    std::fprintf(stderr, "usage: pt-hostile-check --case DIR --manifest FILE --results FILE --source-dir DIR "
                         "--pt-grade PT_GRADE -- COMMAND...\n");
    return 2;
  }
  json expect, manifest;
  try {
    expect = json::parse(read_file(case_dir + "/expect.json"));
    manifest = json::parse(read_file(manifest_path));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-hostile-check: %s\n", e.what());
    return 2;
  }
  const int part = expect.at("part").get<int>();
  std::printf("case %s: %s\n", case_dir.c_str(), expect.value("attack", "").c_str());

  // A case that needs a layer this machine does not offer is skipped before
  // it runs: a fork bomb is not something to try without a process limit.
  const json needs = fallback ? expect["fallback"].value("needs", json::array()) : expect.value("needs", json::array());
  if (!needs.empty()) {
    std::vector<std::string> query{pt_grade, "sandbox"};
    for (size_t i = 0; i < command.size(); ++i)  // the sandbox the command asks for
      if (command[i] == "--no-sandbox")
        query.push_back(command[i]);
      else if ((command[i] == "--sandbox-without" || command[i] == "--sandbox-user") && i + 1 < command.size())
        query.insert(query.end(), {command[i], command[i + 1]});
    std::string info;
    if (run_command(query, &info) != 0) {
      std::fprintf(stderr, "pt-hostile-check: %s sandbox failed\n", pt_grade.c_str());
      return 2;
    }
    const json layers = json::parse(info);
    for (const auto& need : needs) {
      const auto& ids = layers.at("ids");
      if (std::find(ids.begin(), ids.end(), need) == ids.end()) {
        std::printf("SKIPPED: this case needs the sandbox layer \"%s\", which this machine does not offer (%s)\n",
                    need.get<std::string>().c_str(), layers.at("missing").dump().c_str());
        return 77;
      }
    }
  }

  ::unlink(results_path.c_str());
  const double kill_after = expect.value("kill_grader_after", 0.0);
  const int status = run_command(command, nullptr, kill_after);
  const std::string written = read_file(results_path);
  const std::string binary = binary_graded(command);
  std::this_thread::sleep_for(std::chrono::duration<double>(expect.value("settle_seconds", 0.0)));
  const std::string settled = read_file(results_path);

  Checker c;
  const int want_status = kill_after > 0 ? 128 + SIGKILL : 0;
  c.expect(status == want_status,
           "the grader exited with status " + std::to_string(status) + ", not " + std::to_string(want_status));
  // A grader that returns has killed every process of its runs; one that is
  // killed takes them with it within moments (the warden's death signal).
  if (kill_after > 0) std::this_thread::sleep_for(std::chrono::seconds(1));
  const int left = binary.empty() ? 0 : survivors(binary);
  c.expect(left == 0, std::to_string(left) + " process(es) of the graded binary outlived the grader");
  c.expect(!written.empty(), "no results.json at " + results_path);
  c.expect(settled == written, "results.json changed after the grader had finished");
  json results;
  try {
    results = json::parse(settled);
  } catch (const std::exception& e) {
    c.expect(false, std::string("results.json does not parse: ") + e.what());
  }
  const json& pt = results.is_object() ? results["extra_data"]["pt_grade"] : json();
  c.expect(pt.is_object() && pt.value("complete", false) == (kill_after == 0),
           kill_after > 0 ? "results.json says it is complete, yet the grader was killed"
                          : "results.json does not say the grading completed");

  std::map<std::string, json> listed;
  for (const auto& t : results.value("tests", json::array()))
    if (t.contains("extra_data") && t["extra_data"].value("part", 0) == part)
      listed[t["extra_data"].value("test", "")] = t;
  std::set<std::string> lost;
  for (const auto& task : expect.value("lost_tasks", json::array())) lost.insert(task.get<std::string>());
  const std::regex failure(expect.value("failure", ".*"));
  double want_score = 0, got_score = 0, max_score = 0;
  size_t not_run = 0;
  const json& tests = manifest["parts"][std::to_string(part)];
  for (const auto& m : tests) {
    const std::string name = m.at("test");
    const double points = m.at("points");
    max_score += points;
    auto it = listed.find(name);
    if (it == listed.end()) {
      c.expect(false, name + " is missing from results.json");
      continue;
    }
    const json& t = it->second;
    const double score = t.value("score", -1.0), max = t.value("max_score", -1.0);
    const std::string output = t.value("output", "");
    got_score += score;
    not_run += t["extra_data"].value("result", "") == "not-run";
    c.expect(max == points, name + ": max_score " + std::to_string(max) + ", the manifest says " + std::to_string(points));
    if (lost.count(m.at("task"))) {
      c.expect(score == 0, name + " (" + m.at("task").get<std::string>() + ") scored " + std::to_string(score));
      c.expect(std::regex_search(output, failure),
               name + ": its message does not match /" + expect.value("failure", "") + "/: " + output.substr(0, 300));
    } else {
      want_score += points;
      c.expect(score == points, name + " (" + m.at("task").get<std::string>() + ") scored " + std::to_string(score) +
                                    " of " + std::to_string(points) + ": " + output.substr(0, 300));
    }
  }
  c.expect(listed.size() == tests.size(), "results.json lists " + std::to_string(listed.size()) + " tests of part " +
                                              std::to_string(part) + ", the manifest " + std::to_string(tests.size()));
  const double total = results.value("score", -1.0);
  c.expect(std::abs(total - want_score) < 1e-9,
           "total score " + std::to_string(total) + ", expected " + std::to_string(want_score));
  c.expect(std::abs(total - got_score) < 1e-9, "the total is not the sum of the tests' scores");
  if (expect.value("budget_cut", false))
    c.expect(not_run > 0, "no test was left unrun: the part's budget was not what stopped the grading");
  if (expect.contains("note"))
    c.expect(std::regex_search(results.value("output", ""), std::regex(expect["note"].get<std::string>())),
             "no note matching /" + expect["note"].get<std::string>() + "/ in the report's output");
  if (expect.contains("max_results_bytes"))
    c.expect(settled.size() <= expect["max_results_bytes"].get<size_t>(),
             "results.json is " + std::to_string(settled.size()) + " bytes");
  for (const auto& file : expect.value("no_text_of", json::array()))
    for (const auto& line : telling_lines(read_file(source_dir + "/" + file.get<std::string>())))
      if (settled.find(json(line).dump().substr(1, json(line).dump().size() - 2)) != std::string::npos) {
        c.expect(false, "results.json holds a line of " + file.get<std::string>() + ": " + line);
        break;
      }

  std::printf("score %g of %g (expected %g)\n", total, max_score, want_score);
  if (c.failures.empty()) {
    std::printf("honest\n");
    return 0;
  }
  for (const auto& f : c.failures) std::printf("NOT HONEST: %s\n", f.c_str());
  return 1;
}
