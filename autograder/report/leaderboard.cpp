#include "report/leaderboard.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "run/grade_part.h"
#include "run/verdicts.h"

namespace pt::grade {
namespace {

using nlohmann::json;

constexpr const char* kTest = "Part2Leaderboard.DISABLED_Measure";

// Keeps the run's channel bytes; the run ends at `end`.
class MeasureWatch : public RunObserver {
 public:
  explicit MeasureWatch(double seconds)
      : end_(Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))),
        seconds_(seconds) {}
  void on_channel(std::string_view bytes) override {
    if (bytes_.size() < (1u << 20)) bytes_.append(bytes);
  }
  Deadline deadline() const override { return {end_, seconds_}; }
  const std::string& bytes() const { return bytes_; }

 private:
  Clock::time_point end_;
  double seconds_;
  std::string bytes_;
};

// Four significant digits: what a leaderboard shows, and no more than the
// scenes measure.
double rounded(double v) {
  if (v == 0 || !std::isfinite(v)) return v;
  const double scale = std::pow(10.0, 3 - std::floor(std::log10(std::fabs(v))));
  return std::round(v * scale) / scale;
}

}  // namespace

std::map<std::string, double> leaderboard_measures(Sandbox& sandbox, const std::string& verifier,
                                                   const std::string& worker, double seconds, std::string* why) {
  RunRequest request{verifier,
                     {kChannelFlag, "--gtest_also_run_disabled_tests", std::string("--gtest_filter=") + kTest,
                      "--gtest_color=no"},
                     make_key(),
                     ""};
  MeasureWatch watch(seconds);
  RunOutcome worker_run;
  const RunOutcome run = run_with_worker(sandbox, request, watch, worker, worker_run);
  std::map<std::string, double> measures;
  std::istringstream lines(watch.bytes());
  for (std::string line; std::getline(lines, line);) {
    const json record = json::parse(line, nullptr, false);
    // Only the run's own key makes a record: anything else on the channel
    // came from elsewhere.
    if (!record.is_object() || record.value("k", "") != request.key || !record.contains("measure")) continue;
    if (!record["measure"].is_string() || !record.contains("value") || !record["value"].is_number()) continue;
    measures[record["measure"].get<std::string>()] = record["value"].get<double>();
  }
  if (measures.empty() && why)
    *why = "the leaderboard's measurements were not made (" + run.exit.describe() +
           "): the tree did not build on its scenes, or the run ended first";
  return measures;
}

std::vector<LeaderboardEntry> leaderboard_entries(const std::map<std::string, double>& student,
                                                  const std::map<std::string, double>& solution, std::string* why) {
  double log_ratio = 0;
  int scenes = 0;
  for (const auto& [name, cost] : solution) {
    if (name.rfind("sah_cost_", 0) != 0) continue;
    const auto it = student.find(name);
    if (it == student.end() || !(it->second > 0) || !(cost > 0)) {
      if (why) *why = "the leaderboard: no " + name + " for the submission or the solution";
      return {};
    }
    log_ratio += std::log(it->second / cost);
    ++scenes;
  }
  const auto tests = student.find("primitive_tests_per_ray"), nodes = student.find("node_visits_per_ray");
  if (scenes == 0 || tests == student.end() || nodes == student.end()) {
    if (why) *why = "the leaderboard: the measurements are incomplete";
    return {};
  }
  return {{"SAH cost / solution's", rounded(std::exp(log_ratio / scenes)), "asc"},
          {"Primitive tests per ray", rounded(tests->second), "asc"},
          {"Node visits per ray", rounded(nodes->second), "asc"}};
}

void add_leaderboard(Report& report, const std::string& kit, const std::string& verifier, const std::string& worker,
                     Sandbox& sandbox, Clock::time_point deadline) {
  const std::string solution = (std::filesystem::path(kit) / "verifiers" / "part2_worker_reference").string();
  if (verifier.empty() || worker.empty() || !std::filesystem::is_regular_file(solution)) {
    report.notes.push_back("the leaderboard: part 2 was not graded beside a worker, or the kit has no " + solution);
    return;
  }
  const double seconds = std::min(60.0, std::chrono::duration<double>(deadline - Clock::now()).count() / 2);
  if (seconds < 5) {
    report.notes.push_back("the leaderboard: not measured, the submission's time budget ran out");
    return;
  }
  std::string why;
  const auto mine = leaderboard_measures(sandbox, verifier, worker, seconds, &why);
  const auto theirs = mine.empty() ? mine : leaderboard_measures(sandbox, verifier, solution, seconds, &why);
  report.leaderboard = theirs.empty() ? std::vector<LeaderboardEntry>() : leaderboard_entries(mine, theirs, &why);
  if (report.leaderboard.empty()) report.notes.push_back(why);
}

}  // namespace pt::grade
