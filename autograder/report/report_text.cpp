#include "report/report_text.h"

#include <algorithm>
#include <cstdio>

namespace pt::grade {
namespace {

// The length of the UTF-8 sequence starting at text[i], or 0 when it is not
// a valid one (each of its bytes then becomes a replacement character).
size_t utf8_length(std::string_view text, size_t i) {
  const auto c = static_cast<unsigned char>(text[i]);
  size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(text[i + k]) >> 6) != 0x2) return 0;
  return n;
}

// What the character at text[i] costs in JSON, and how many bytes it takes.
std::pair<size_t, size_t> next_char(std::string_view text, size_t i) {
  const auto c = static_cast<unsigned char>(text[i]);
  if (c == '"' || c == '\\' || c == '\n' || c == '\t' || c == '\r' || c == '\b' || c == '\f') return {2, 1};
  if (c < 0x20) return {6, 1};
  const size_t n = utf8_length(text, i);
  return n == 0 ? std::pair<size_t, size_t>{3, 1} : std::pair<size_t, size_t>{n, n};
}

std::string cut_note(size_t cut_bytes, size_t total_bytes) {
  return "\n[... pt-grade cut " + std::to_string(cut_bytes) + " of these " + std::to_string(total_bytes) +
         " bytes: a report has a bounded size ...]";
}

}  // namespace

size_t json_cost(std::string_view text) {
  size_t cost = 0;
  for (size_t i = 0; i < text.size();) {
    const auto [c, n] = next_char(text, i);
    cost += c;
    i += n;
  }
  return cost;
}

std::string capped(std::string_view text, size_t max_cost) {
  // One walk, never past the bound: a text of megabytes costs only its head.
  const size_t note_room = 96;  // the note's own cost, at most
  const size_t budget = max_cost > note_room ? max_cost - note_room : 0;
  size_t cost = 0, i = 0, cut_at = std::string_view::npos;
  while (i < text.size()) {
    const auto [c, n] = next_char(text, i);
    if (cut_at == std::string_view::npos && cost + c > budget) cut_at = i;
    if (cost + c > max_cost) return std::string(text.substr(0, cut_at)) + cut_note(text.size() - cut_at, text.size());
    cost += c;
    i += n;
  }
  return std::string(text);
}

std::string capped_list(const std::vector<std::string>& items, size_t max_items, size_t max_item_cost) {
  std::string out;
  for (size_t i = 0; i < items.size() && i < max_items; ++i) out += capped(items[i], max_item_cost) + "\n";
  if (items.size() > max_items)
    out += "[... and " + std::to_string(items.size() - max_items) + " more, not listed: a report has a bounded size]\n";
  return out;
}

TextBounds TextBounds::halved() const {
  auto half = [](size_t v) { return std::max<size_t>(v / 2, 256); };
  return {half(message), half(output), half(note), half(notes)};
}

std::string summary(std::string_view text, const std::string& rest_is) {
  std::string_view body = text;
  while (!body.empty() && body.back() == '\n') body.remove_suffix(1);
  if (std::count(body.begin(), body.end(), '\n') < static_cast<long>(kSummaryLines) &&
      json_cost(body) <= kSummaryBytes)
    return std::string(text);
  // At most kSummaryLines - 1 lines and the pointer to the rest: a summary is
  // its own summary.
  const std::string rest = "[... " + rest_is + "]";
  const size_t budget = kSummaryBytes > json_cost(rest) + 2 ? kSummaryBytes - json_cost(rest) - 2 : 0;
  size_t cost = 0, i = 0, lines = 0;
  while (i < body.size()) {
    const auto [c, n] = next_char(body, i);
    if (cost + c > budget || (body[i] == '\n' && ++lines == kSummaryLines - 1)) break;
    cost += c;
    i += n;
  }
  return std::string(body.substr(0, i)) + "\n" + rest;
}

std::string number(double v, const char* format) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string points_number(double v) {
  std::string s = number(v, "%.2f");
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string points_text(double v) { return points_number(v) + (v == 1 ? " point" : " points"); }

}  // namespace pt::grade
