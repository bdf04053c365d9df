#include "report/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "report/atomic_file.h"
#include "report/report_text.h"

namespace pt::grade {
namespace {

using nlohmann::json;

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

}  // namespace

std::string HiddenNotRun::text() const {
  return std::to_string(tests) + " tests, " + points_text(points);
}

void Tally::add(const TestResult& t) {
  ++total;
  passed += t.passed();
  earned += t.passed() ? t.test.points : 0;
  possible += t.test.points;
}
std::string Tally::tests() const { return std::to_string(passed) + " / " + std::to_string(total); }
std::string Tally::points() const { return points_number(earned) + " / " + points_number(possible); }

std::string test_title(const TestResult& t) {
  return t.test.task + " " + t.test.name + (t.test.uncounted() ? " (extension, not counted)" : "");
}

std::vector<std::string> all_notes(const Report& report, const TextBounds& bounds) {
  std::vector<std::string> notes = report.notes;
  for (const auto& p : report.parts)
    for (const auto& n : p.notes) notes.push_back("part " + std::to_string(p.part) + ": " + n);
  std::vector<std::string> kept;
  size_t cost = 0;
  for (size_t i = 0; i < notes.size(); ++i) {
    std::string note = capped(notes[i], bounds.note);
    cost += json_cost(note) + 2;
    if (cost > bounds.notes) {
      kept.push_back("[... and " + std::to_string(notes.size() - i) + " more notes, not shown: a report has a bounded size]");
      break;
    }
    kept.push_back(std::move(note));
  }
  return kept;
}


std::string folded(const std::string& text, const std::string& indent, size_t width) {
  std::string out;
  const size_t size = text.find_last_not_of('\n') + 1;  // npos + 1 == 0: nothing but newlines
  size_t pos = 0;
  while (pos < size) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos || end > size) end = size;
    std::string_view line(text.data() + pos, end - pos);
    bool continuation = false;
    do {
      // Continuation lines are marked so that a reader sees one line folded,
      // not two lines.
      const std::string lead = indent + (continuation ? "  " : "");
      std::string_view piece = line;
      if (line.size() > width) {
        const size_t space = line.rfind(' ', width);
        piece = line.substr(0, space != std::string_view::npos && space > width / 2 ? space + 1 : width);
      }
      out += lead;
      out += piece;
      out += "\n";
      line.remove_prefix(piece.size());
      continuation = true;
    } while (!line.empty());
    pos = end + 1;
  }
  return out;
}

namespace {

json results_document(const Report& report, const TextBounds& bounds) {
  json tests = json::array(), parts = json::object();
  Tally all;
  for (const auto& p : report.parts) {
    for (const auto& t : p.tests) {
      all.add(t);
      tests.push_back({{"name", test_title(t)},
                       {"score", t.passed() ? t.test.points : 0.0},
                       {"max_score", t.test.points},
                       {"status", t.passed() ? "passed" : "failed"},
                       {"output", test_output(t, bounds)},
                       {"visibility", t.test.hidden ? "after_published" : "visible"},
                       {"extra_data",
                        {{"part", p.part},
                         {"test", t.test.name},
                         {"task", t.test.task},
                         {"result", t.status_name()},
                         {"seconds", std::round(t.seconds * 1000) / 1000}}}});
    }
    parts[std::to_string(p.part)] = {
        {"earned", p.earned()}, {"possible", p.possible()}, {"graded", p.graded}, {"runs", p.runs}, {"seconds", p.seconds}};
  }
  std::string text;
  for (const auto& n : all_notes(report, bounds)) text += n + "\n";
  json doc = {{"score", all.earned},
              {"execution_time", std::round(report.seconds * 10) / 10},
              {"tests", tests},
              {"extra_data",
               {{"pt_grade",
                 {{"complete", report.complete},
                  {"parts", parts},
                  {"sandbox",
                   {{"layers", report.sandbox_layers},
                    {"missing", report.sandbox_missing},
                    {"ids", report.sandbox_ids}}}}}}}};
  if (!text.empty()) doc["output"] = text;
  if (!report.leaderboard.empty()) {
    json board = json::array();
    for (const auto& e : report.leaderboard) board.push_back({{"name", e.name}, {"value", e.value}, {"order", e.order}});
    doc["leaderboard"] = board;
  }
  return doc;
}

}  // namespace

std::string test_output(const TestResult& t, const TextBounds& bounds) {
  std::string output = t.passed() ? "" : capped(t.message, bounds.message);
  if (!t.output.empty()) output += "\n\nLast output before it stopped:\n" + capped(t.output, bounds.output);
  return output;
}

std::string fitted_document(const std::function<std::string(const TextBounds&)>& document, size_t max_bytes) {
  TextBounds bounds;
  for (;;) {
    std::string text = document(bounds);
    if (text.size() <= max_bytes || bounds.message <= 256) return text;
    bounds = bounds.halved();
  }
}

void write_results_json(const std::string& path, const Report& report) {
  write_file_atomically(path, fitted_document(
                                  [&](const TextBounds& bounds) {
                                    // Messages are whatever the tests printed: never let bad UTF-8 stop the report.
                                    return results_document(report, bounds).dump(2, ' ', false,
                                                                                  json::error_handler_t::replace) +
                                           "\n";
                                  },
                                  kMaxResultsBytes));
}

void print_report(const Report& report, bool show_hidden) {
  std::printf("\n%-6s %-14s %-14s %s\n", "part", "tests passed", "points", "");
  Tally all;
  HiddenNotRun all_unrun;
  for (const auto& p : report.parts) {
    Tally part, hidden, uncounted;
    for (const auto& t : p.tests) {
      part.add(t);
      all.add(t);
      if (t.test.hidden) hidden.add(t);
      if (t.test.uncounted()) uncounted.add(t);
    }
    std::vector<std::string> extra;
    if (!p.graded) extra.push_back("not graded");
    if (hidden.total > 0) extra.push_back("including hidden: " + hidden.tests() + " tests, " + hidden.points() + " points");
    if (uncounted.total > 0) extra.push_back("including extension tests, not counted: " + uncounted.tests());
    if (auto it = report.hidden_not_run.find(p.part); it != report.hidden_not_run.end() && it->second.tests > 0) {
      extra.push_back("hidden: " + it->second.text() + " not run here");
      all_unrun.tests += it->second.tests;
      all_unrun.points += it->second.points;
    }
    std::printf("%-6d %-14s %-14s %s\n", p.part, part.tests().c_str(), part.points().c_str(),
                joined(extra, "; ").c_str());
  }
  const std::string unrun =
      all_unrun.tests == 0 ? "" : "hidden: " + points_text(all_unrun.points) + " not run here (the grader runs them)";
  std::printf("%-6s %-14s %-14s %s\n", "total", all.tests().c_str(), all.points().c_str(), unrun.c_str());

  bool header = false;
  for (const auto& p : report.parts) {
    bool failed = false;
    for (const auto& t : p.tests) {
      if (t.passed()) continue;
      if (!header) std::printf("\nFailed graded tests:\n");
      header = failed = true;
      if (t.test.hidden && !show_hidden) {
        std::printf("  %s (hidden test, %s)\n", t.test.task.c_str(), points_text(t.test.points).c_str());
        continue;
      }
      std::printf("  %s %s%s (%s%s)\n", t.test.task.c_str(), t.test.name.c_str(), t.test.hidden ? " [hidden]" : "",
                  points_text(t.test.points).c_str(),
                  t.test.uncounted() ? ": an extension task, not counted" : "");
      const TextBounds bounds;
      std::fputs(folded(capped(t.message, bounds.message), "      ").c_str(), stdout);
      if (!t.output.empty()) {
        std::printf("      last output:\n");
        std::fputs(first_lines(capped(t.output, bounds.output), 12, "      | ").c_str(), stdout);
      }
    }
    if (failed && !p.log.empty()) std::printf("      (part %d output: %s)\n", p.part, p.log.c_str());
  }
  const auto notes = all_notes(report, TextBounds{});
  if (!notes.empty()) std::printf("\nNotes:\n");
  for (const auto& n : notes) std::fputs(folded(n, "  ").c_str(), stdout);
  std::fflush(stdout);
}

std::map<std::string, double> test_seconds_from_results(const std::string& path) {
  std::map<std::string, double> seconds;
  std::ifstream in(path);
  const json doc = json::parse(in, nullptr, false);  // a missing file or bad JSON: discarded, not an object
  if (!doc.is_object() || !doc.contains("tests") || !doc["tests"].is_array()) return seconds;
  for (const auto& t : doc["tests"]) {
    const json extra = t.is_object() ? t.value("extra_data", json()) : json();
    if (extra.is_object() && extra.value("test", json()).is_string() && extra.value("seconds", json()).is_number())
      seconds[extra["test"].get<std::string>()] = extra["seconds"].get<double>();
  }
  return seconds;
}

}  // namespace pt::grade
