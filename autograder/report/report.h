#pragma once
// What a grading produced, and its two renderings: the score table a person
// reads in a terminal, and Gradescope's results.json.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "run/grade_part.h"

namespace pt::grade {

// Hidden tests a build without them could not run (the student release): the
// table says how many points they are worth, so that a full visible score is
// never read as full marks.
struct HiddenNotRun {
  int tests = 0;
  double points = 0;
  std::string text() const;  // "5 tests, 6.5 points"
};

// One entry of Gradescope's leaderboard (leaderboard.h): order "asc" when
// smaller is better.
struct LeaderboardEntry {
  std::string name;
  double value = 0;
  std::string order;
};

struct Report {
  std::vector<PartResult> parts;
  std::map<int, HiddenNotRun> hidden_not_run;  // by part
  std::vector<std::string> notes;  // for the instructor: missing binaries, sandbox layers missing, ...
  std::vector<std::string> sandbox_layers, sandbox_missing, sandbox_ids;
  // results.json's "leaderboard", written only when not empty: only when the
  // instructor turned it on (pt-grade submission --leaderboard).
  std::vector<LeaderboardEntry> leaderboard;
  double seconds = 0;
  // Why the submission as a whole could not be graded ("" when it was): it
  // was refused before anything was built (no task file, a file that is not
  // one), or the grader itself failed. A part that does not build or run is
  // graded: it scores 0.
  std::string ungradable;
  bool complete = false;  // every part graded (false while grading, or after a budget ran out)
};

// Tests passed and points earned among some tests: a part's, a task's, all.
struct Tally {
  int passed = 0, total = 0;
  double earned = 0, possible = 0;
  void add(const TestResult& t);
  std::string tests() const;   // "3 / 4"
  std::string points() const;  // "2.5 / 4"
};

// "P5T3 Suite.Name (extension, not counted)": a test as the result files name it.
std::string test_title(const TestResult& t);

struct TextBounds;

// Every note of the report (the parts' with their part named), each and all
// together within `bounds` (report_text.h).
std::vector<std::string> all_notes(const Report& report, const TextBounds& bounds);

// What a report says of one test: its failure message (nothing when it
// passed) and, for a test that hung or crashed, the last output before it
// stopped, each within `bounds`.
std::string test_output(const TestResult& test, const TextBounds& bounds);

// A report's text within max_bytes whatever the submission did: `document`
// made with the default bounds, then with the bounds halved until it fits
// (every text is capped, so halving them bounds the file for any number of
// tests), or until a message's bound reaches 256 bytes.
std::string fitted_document(const std::function<std::string(const TextBounds&)>& document, size_t max_bytes);

// Writes Gradescope's results.json atomically (temporary file, rename): a
// reader, or a grader killed half-way, sees one whole report or the previous
// one. Every test of every part is listed with its points, graded or not.
// Every text in it is capped (report_text.h) and the file is at most
// kMaxResultsBytes, whatever the submission did. Throws std::runtime_error when the file cannot be written.
void write_results_json(const std::string& path, const Report& report);

// The seconds each test took in a results.json written as above (its tests'
// extra_data); empty when the file is missing or not one of ours.
std::map<std::string, double> test_seconds_from_results(const std::string& path);

// The score table, the failed tests with their whole messages (hidden ones by
// task only, unless show_hidden; long lines folded, never cut) and the notes,
// on stdout.
void print_report(const Report& report, bool show_hidden);

// `text` with every line indented and folded at `width` columns (at a space
// where there is one), nothing left out.
std::string folded(const std::string& text, const std::string& indent, size_t width = 100);

}  // namespace pt::grade
