#pragma once
// Every text that flows from a submission into a report (results.json,
// report.html, the score table on stdout) has a size: what a submission
// prints, throws, names or makes a compiler say is cut to a bound, with a
// note of what was cut, so that no submission can make a report too large
// for Gradescope (which refuses or truncates results past about 1 MiB), the
// disk or a reader. A size here is what the text costs in JSON: a control
// character is 6 bytes there ("\u001b"), a quote or a backslash 2, a byte of
// broken UTF-8 3 (the replacement character it becomes).
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace pt::grade {

// The bytes `text` takes inside a JSON string (without the quotes).
size_t json_cost(std::string_view text);

// `text` itself when its JSON cost is at most max_cost; else its head, cut at
// a character boundary, and a line saying how much was cut.
std::string capped(std::string_view text, size_t max_cost);

// At most max_items of `items`, each capped, then a line saying how many were
// left out: for lists a submission can make as long as it likes (intake
// refusals, files the compiler read).
std::string capped_list(const std::vector<std::string>& items, size_t max_items, size_t max_item_cost);

// The bounds (JSON cost) of each kind of text in a report.
struct TextBounds {
  size_t message = 4096;    // a test's failure message
  size_t output = 2048;     // a test's last output before it stopped
  size_t note = 16384;      // one note
  size_t notes = 65536;     // all notes together
  TextBounds halved() const;
};

// results.json is written within this many bytes whatever the submission
// does (TextBounds are halved until it fits).
inline constexpr size_t kMaxResultsBytes = 1000000;

// A part-level text (an intake refusal, a build failure) is given once, in the
// part's notes; each test of the part says only its first lines, within these.
inline constexpr size_t kSummaryLines = 6, kSummaryBytes = 1024;

// `text` itself when short; else its first lines within kSummaryLines and
// kSummaryBytes and a line saying where the rest is.
std::string summary(std::string_view text, const std::string& rest_is);

// A number as the reports show it: printf's `format`.
std::string number(double v, const char* format = "%g");
// "0.5", "12", "33.1": points at the precision they are given in (hundredths).
std::string points_number(double v);
// "1 point", "2.5 points".
std::string points_text(double v);

// "1, 3": each item (a number or a text) with `separator` between them.
template <class Items>
std::string joined(const Items& items, const std::string& separator) {
  std::string out;
  for (const auto& item : items) {
    out += out.empty() ? "" : separator;
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(item)>>) out += std::to_string(item);
    else out += item;
  }
  return out;
}

}  // namespace pt::grade
