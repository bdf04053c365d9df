#include "report/html_report.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "report/atomic_file.h"
#include "report/report_text.h"

namespace pt::grade {

namespace {

std::string esc(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (unsigned char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        // Control characters a test printed would make the page invalid.
        if (c < 0x20 && c != '\n' && c != '\t') out += "\xEF\xBF\xBD";
        else out += static_cast<char>(c);
    }
  }
  return out;
}

const char* kStyle = R"(
body{font:15px/1.45 system-ui,sans-serif;margin:2em auto;max-width:1100px;color:#222;padding:0 1em}
h1{font-size:1.6em;margin-bottom:.2em} h2{margin-top:1.8em;border-bottom:1px solid #ddd}
table{border-collapse:collapse;margin:.5em 0} td,th{padding:.25em .7em;border:1px solid #ddd;text-align:left;vertical-align:top}
th{background:#f4f4f4} .num{text-align:right;font-variant-numeric:tabular-nums}
.full{background:#e7f6e7} .part{background:#fff6df} .zero{background:#fbe4e4}
.fail{border-left:4px solid #c33;padding:.3em .8em;margin:.8em 0;background:#fcfcfc}
.fail h3{font-size:1em;margin:.2em 0} .tag{font-size:.8em;padding:.05em .4em;border-radius:3px;background:#eee;margin-left:.4em}
.hidden-tag{background:#e7e0f6} pre{white-space:pre-wrap;background:#f6f6f6;padding:.6em;font-size:.85em;max-height:22em;overflow:auto}
.renders{display:grid;grid-template-columns:repeat(3,1fr);gap:.6em;margin:.5em 0 1.5em}
.test-images{grid-template-columns:repeat(4,1fr)} .renders figure{margin:0} .renders img{width:100%;image-rendering:pixelated;border:1px solid #ccc}
figcaption{font-size:.85em;color:#555} .flag{color:#b00;font-weight:600} .ok{color:#070}
.muted{color:#666;font-size:.9em}
)";

std::string score_class(double earned, double possible) {
  if (possible <= 0) return "";
  return earned >= possible ? "full" : earned > 0 ? "part" : "zero";
}

// A handout heading as text: without Markdown's backticks.
std::string plain(std::string md) {
  md.erase(std::remove(md.begin(), md.end(), '`'), md.end());
  return md;
}

// "handouts/part1.md §3. Triangle intersection (P1T3)", escaped; "" for a task no handout names.
std::string handout_section(const HandoutIndex& handouts, const std::string& task) {
  const auto ref = handouts.tasks.find(task);
  return ref == handouts.tasks.end() ? "" : esc(ref->second.file + " §" + plain(ref->second.section));
}

std::string image(const std::string& path, const std::string& alt, size_t* image_bytes) {
  const std::string b64 = base64_file(path);
  if (b64.empty()) return "<div class=muted>(" + esc(alt) + ": no image)</div>";
  *image_bytes += b64.size();
  return "<img alt=\"" + esc(alt) + "\" src=\"data:image/png;base64," + b64 + "\">";
}

// A failing image test's images in a row, each captioned, while the page's
// bound on them lasts.
std::string test_images(const TestResult& t, size_t* shown, size_t* image_bytes) {
  if (t.images.empty()) return "";
  size_t bytes = 0;
  for (const auto& i : t.images) bytes += i.png.size();
  if (*shown + bytes > kMaxTestImageBytesOnPage)
    return "<div class=muted>(its images are left out: the page already shows " + std::to_string(*shown) +
           " bytes of test images, its bound)</div>";
  *shown += bytes;
  std::string out = "<div class=\"renders test-images\">";
  for (const auto& i : t.images) {
    const std::string b64 = base64_text(i.png);
    *image_bytes += b64.size();
    out += "<figure><img alt=\"" + esc(i.name) + "\" src=\"data:image/png;base64," + b64 + "\"><figcaption>" +
           esc(i.caption) + "</figcaption></figure>";
  }
  return out + "</div>";
}

}  // namespace

std::string base64_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream s;
  s << in.rdbuf();
  return base64_text(s.str());
}

std::string base64_text(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned b0 = static_cast<unsigned char>(bytes[i]);
    const unsigned b1 = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
    const unsigned b2 = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0;
    const unsigned v = (b0 << 16) | (b1 << 8) | b2;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[v & 63] : '=';
  }
  return out;
}

namespace {

// The page with every text within `bounds`; *image_bytes: what its images take.
std::string html_page(const HtmlReport& page, const TextBounds& bounds, size_t* image_bytes) {
  const Report& r = *page.report;
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8>"
    << "<meta name=viewport content=\"width=device-width,initial-scale=1\">"
    << "<title>" << esc(page.title) << " — path tracer grade</title><style>" << kStyle << "</style></head><body>\n";

  double earned = 0, possible = 0;
  for (const auto& p : r.parts) {
    earned += p.earned();
    possible += p.possible();
  }
  h << "<h1>" << esc(page.title) << "</h1>\n<p><b>" << number(earned) << " / " << number(possible) << " points</b>"
    << " <span class=muted>graded in " << number(r.seconds, "%.0f") << " s"
    << (r.complete ? "" : "; <span class=flag>incomplete: the grader stopped before the end</span>") << "</span></p>\n";

  // Score per part and per task.
  h << "<h2>Score</h2>\n<table><tr><th>part</th><th>task</th><th>tests passed</th><th>points</th><th>handout</th></tr>\n";
  for (const auto& p : r.parts) {
    std::map<std::string, Tally> tasks;
    for (const auto& t : p.tests) tasks[t.test.task].add(t);
    bool first = true;
    for (const auto& [task, tally] : tasks) {
      h << "<tr>";
      if (first)
        h << "<td rowspan=" << tasks.size() << " class=\"" << score_class(p.earned(), p.possible()) << "\"><b>Part "
          << p.part << "</b><br>" << number(p.earned()) << " / " << number(p.possible()) << "</td>";
      first = false;
      h << "<td>" << esc(task) << "</td><td class=num>" << tally.tests() << "</td><td class=\"num "
        << score_class(tally.earned, tally.possible) << "\">" << number(tally.earned) << " / "
        << number(tally.possible) << "</td><td>" << handout_section(page.handouts, task) << "</td></tr>\n";
    }
  }
  h << "</table>\n";

  // Failures.
  h << "<h2>Failed tests</h2>\n";
  bool any_failure = false;
  size_t test_image_bytes = 0;
  for (const auto& p : r.parts) {
    // A part that was not submitted, not built or rejected fails every test
    // with one reason: say it once.
    bool one_reason = !p.tests.empty();
    for (const auto& t : p.tests) one_reason = one_reason && !t.passed() && t.message == p.tests.front().message;
    if (one_reason && p.tests.size() > 1) {
      any_failure = true;
      h << "<div class=fail><h3>Part " << p.part << ": all " << p.tests.size() << " tests, " << number(p.possible())
        << " points</h3><pre>" << esc(capped(p.tests.front().message, bounds.message)) << "</pre></div>\n";
      continue;
    }
    for (const auto& t : p.tests) {
      if (t.passed()) continue;
      any_failure = true;
      h << "<div class=fail><h3>" << esc(t.test.task) << " " << esc(t.test.name) << "<span class=tag>"
        << points_text(t.test.points) << "</span>"
        << (t.test.hidden ? "<span class=\"tag hidden-tag\">hidden</span>" : "")
        << (t.test.extension ? "<span class=tag>extension</span>" : "") << "<span class=tag>"
        << esc(t.status_name()) << "</span></h3>";
      auto row = page.handouts.test_rows.find(t.test.name);
      if (row != page.handouts.test_rows.end()) h << "<div class=muted>Checks: " << esc(plain(row->second)) << "</div>";
      if (page.handouts.tasks.count(t.test.task))
        h << "<div class=muted>Read: " << handout_section(page.handouts, t.test.task) << "</div>";
      h << "<pre>" << esc(capped(t.message, bounds.message)) << "</pre>";
      if (!t.output.empty())
        h << "<div class=muted>Last output before it stopped:</div><pre>" << esc(capped(t.output, bounds.output))
          << "</pre>";
      h << test_images(t, &test_image_bytes, image_bytes);
      h << "</div>\n";
    }
  }
  if (!any_failure) h << "<p class=ok>Every graded test passed.</p>\n";

  // Renders.
  h << "<h2>Renders</h2>\n";
  if (!page.renders_note.empty()) h << "<p class=muted>" << esc(page.renders_note) << "</p>\n";
  for (const auto& c : page.renders) {
    h << "<h3>" << esc(c.scene) << " <span class=muted>" << esc(c.purpose) << "</span></h3>\n<p>";
    const std::string parts = joined(c.student_parts, ", ");
    h << esc(c.settings) << "; the submission's part(s) " << (parts.empty() ? "none" : parts)
      << ", the solution for the rest. ";
    if (!c.error.empty()) {
      h << "<span class=flag>The render failed: " << esc(capped(c.error, bounds.note)) << "</span></p>\n";
      continue;
    }
    if (c.relmse >= 0) {
      h << "relMSE " << number(c.relmse, "%.3g");
      if (c.expected_relmse >= 0)
        h << " (the solution's own noise at this sample count: " << number(c.expected_relmse, "%.3g") << ", bound "
          << number(c.bound, "%.3g") << ")";
      h << (c.flagged ? " <span class=flag>far beyond what the sample count explains" +
                            (c.suspect.empty() ? std::string() : ": look at " + esc(c.suspect)) + "</span>"
                      : " <span class=ok>within what the sample count explains</span>");
    }
    h << "</p>\n<div class=renders><figure>" << image(c.student_png, "submission", image_bytes) << "<figcaption>submission</figcaption></figure>"
      << "<figure>" << image(c.reference_png, "reference", image_bytes) << "<figcaption>stored reference</figcaption></figure>"
      << "<figure>" << image(c.difference_png, "difference", image_bytes)
      << "<figcaption>|difference| of illuminance, false colour: red = "
      << (c.difference_scale > 0 ? number(c.difference_scale, "%.3g") + ", twice the 99th percentile of a correct render's noise"
                                 : std::string("the 99th percentile"))
      << "</figcaption></figure></div>\n";
    if (!c.detail.empty()) h << "<p class=muted>" << esc(capped(c.detail, bounds.note)) << "</p>\n";
  }

  // For the instructor.
  h << "<h2>For the instructor</h2>\n";
  const std::vector<std::string> notes = all_notes(r, bounds);
  if (!notes.empty()) {
    h << "<ul>";
    for (const auto& n : notes) h << "<li><pre>" << esc(n) << "</pre></li>";
    h << "</ul>";
  }
  if (!r.sandbox_layers.empty())
    h << "<p class=muted>Sandbox layers: " << esc(joined(r.sandbox_layers, "; "))
      << (r.sandbox_missing.empty() ? "" : ". Missing: " + esc(joined(r.sandbox_missing, "; "))) << ".</p>\n";
  h << "</body></html>\n";
  return h.str();
}

}  // namespace

void write_html_report(const std::string& path, const HtmlReport& page) {
  TextBounds bounds;
  std::string text;
  for (;;) {
    size_t image_bytes = 0;
    text = html_page(page, bounds, &image_bytes);
    if (text.size() - image_bytes <= kMaxHtmlTextBytes || bounds.message <= 256) break;
    bounds = bounds.halved();
  }
  write_file_atomically(path, text);
}

}  // namespace pt::grade
