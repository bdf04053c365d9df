#include "report/prairielearn_report.h"

#include <map>

#include <nlohmann/json.hpp>
#include <stb_image.h>
#include <stb_image_write.h>

#include "report/atomic_file.h"
#include "report/report_text.h"

namespace pt::grade {

namespace {

using nlohmann::json;

std::string g3(double v) { return number(v, "%.3g"); }

// One scene's render in a line: how it was judged, or why there is none.
std::string render_line(const RenderComparison& c) {
  std::string line = c.scene + " (" + c.settings + "): ";
  if (!c.error.empty()) return line + c.error;
  line += "relMSE " + g3(c.relmse) + ", expected " + g3(c.expected_relmse) + ", bound " + g3(c.bound);
  if (c.flagged) line += ": beyond what its sample count explains" + (c.suspect.empty() ? "" : ", most likely " + c.suspect);
  return line;
}

const char* const kPngUrl = "data:image/png;base64,";

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

// A PNG's data: URL, at 1/shrink of its size each way (each new pixel the
// mean of shrink x shrink), "" when it cannot be read. The PNGs are the
// kit's: the stored references, and what pt-library-check drew from a
// render (the student's code made only the EXR's numbers).
std::string png_url(const std::string& path, int shrink) {
  if (shrink == 1) {
    const std::string b64 = base64_file(path);
    return b64.empty() ? "" : kPngUrl + b64;
  }
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!pixels) return "";
  const int sw = w / shrink, sh = h / shrink;
  std::vector<unsigned char> small(static_cast<size_t>(sw) * sh * 3);
  for (int y = 0; y < sh; ++y)
    for (int x = 0; x < sw; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int dy = 0; dy < shrink; ++dy)
          for (int dx = 0; dx < shrink; ++dx) sum += pixels[((y * shrink + dy) * w + x * shrink + dx) * 3 + c];
        small[(static_cast<size_t>(y) * sw + x) * 3 + c] = static_cast<unsigned char>(sum / (shrink * shrink));
      }
  stbi_image_free(pixels);
  std::string png;
  if (sw == 0 || sh == 0 || !stbi_write_png_to_func(append_bytes, &png, sw, sh, 3, small.data(), sw * 3)) return "";
  return kPngUrl + base64_text(png);
}

// The renders as images, submission beside reference, scene by scene while
// both fit in kMaxImageBytes together, at 1/shrink of their size each way;
// *left_out counts the scenes dropped.
json render_images(const HtmlReport& page, int shrink, int* left_out) {
  json images = json::array();
  size_t used = 0;
  *left_out = 0;
  for (const auto& c : page.renders) {
    if (!c.error.empty() || c.student_png.empty()) continue;
    const std::string student = png_url(c.student_png, shrink);
    const std::string reference = png_url(c.reference_png, shrink);
    if (student.empty() || reference.empty()) continue;  // the render's line in the output says what it showed
    if (used + student.size() + reference.size() > kMaxImageBytes) {
      ++*left_out;
      continue;
    }
    used += student.size() + reference.size();
    const std::string verdict = c.flagged ? "flagged, relMSE " + g3(c.relmse) + " above " + g3(c.bound)
                                          : "relMSE " + g3(c.relmse) + ", within " + g3(c.bound);
    images.push_back({{"label", c.scene + ": your render (parts " + joined(c.student_parts, ", ") + "; " + verdict + ")"},
                      {"url", student}});
    images.push_back({{"label", c.scene + ": stored reference"}, {"url", reference}});
  }
  return images;
}

// What the handout says a test checks, and the section of its task.
std::string description(const TestResult& t, const HandoutIndex& handouts) {
  std::string text;
  if (!t.test.hidden)
    if (auto row = handouts.test_rows.find(t.test.name); row != handouts.test_rows.end()) text = row->second;
  if (auto ref = handouts.tasks.find(t.test.task); ref != handouts.tasks.end())
    text += (text.empty() ? "" : " ") + std::string("(") + ref->second.file + ", section " + ref->second.section + ")";
  return text;
}

json tests_of(const Report& report, const HandoutIndex& handouts, const TextBounds& bounds, Tally* all) {
  json tests = json::array();
  std::map<std::string, int> hidden_count;  // by task
  for (const auto& p : report.parts)
    for (const auto& t : p.tests) {
      all->add(t);
      json test = {{"points", t.passed() ? t.test.points : 0.0}, {"max_points", t.test.points}, {"message", t.status_name()}};
      if (t.test.hidden) {
        test["name"] = t.test.task + " hidden test " + std::to_string(++hidden_count[t.test.task]) +
                       (t.test.uncounted() ? " (extension, not counted)" : "");
        test["description"] = "A hidden test: its name and messages are for the instructor. " + description(t, handouts);
        test["output"] = "";
      } else {
        test["name"] = test_title(t);
        test["description"] = description(t, handouts);
        test["output"] = test_output(t, bounds);
      }
      tests.push_back(std::move(test));
    }
  return tests;
}

std::string document(const HtmlReport& page, const json& images, int shrink, int left_out, const TextBounds& bounds) {
  const Report& report = *page.report;
  std::string output;
  for (const auto& n : all_notes(report, bounds)) output += n + "\n";
  json doc;
  if (!report.ungradable.empty()) {
    // No test ran: a list of zeros would read as a grade.
    const std::string why = capped(report.ungradable, bounds.note);
    doc = {{"gradable", false}, {"score", 0.0}, {"message", "Not graded: " + summary(why, "see the output")},
           {"format_errors", json::array({why})}, {"output", output}, {"images", json::array()}, {"tests", json::array()}};
  } else {
    Tally all;
    json tests = tests_of(report, page.handouts, bounds, &all);
    output += "\nRenders: " + page.renders_note + "\n";
    for (const auto& c : page.renders) output += "  " + capped(render_line(c), bounds.note) + "\n";
    if (shrink > 1 && !images.empty())
      output += "  The images are shown at 1/" + std::to_string(shrink) + " of their size each way, to fit " +
                "PrairieLearn's 1 MB\n";
    if (left_out > 0)
      output += "  " + std::to_string(left_out) + " scene(s) rendered but not shown: PrairieLearn takes at most 1 MB " +
                "of results, and the images shown use " + std::to_string(kMaxImageBytes / 1000) + " kB of it\n";
    std::string message = all.points() + " points.";
    if (!report.complete) message += " Grading stopped before every part was graded: see the output.";
    doc = {{"gradable", true}, {"score", all.possible > 0 ? all.earned / all.possible : 0.0}, {"message", message},
           {"output", output}, {"images", images}, {"tests", std::move(tests)}};
  }
  // Messages are whatever the tests printed: never let bad UTF-8 stop the report.
  return doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace

std::string prairielearn_json(const HtmlReport& page) {
  // Full size while every scene fits, else half size (a quarter of the bytes).
  int shrink = 1, left_out = 0;
  json images = render_images(page, shrink, &left_out);
  if (left_out > 0) images = render_images(page, shrink = 2, &left_out);
  const size_t image_bytes = images.dump().size();
  auto fitted = [&] {
    return fitted_document([&](const TextBounds& b) { return document(page, images, shrink, left_out, b); },
                           kMaxResultsBytes);
  };
  std::string text = fitted();
  if (text.size() > kMaxResultsBytes && image_bytes > 2) {  // the text at its smallest and the images do not fit together
    left_out += static_cast<int>(images.size() / 2);
    images = json::array();
    text = fitted();
  }
  return text;
}

void write_prairielearn_json(const std::string& path, const HtmlReport& page) {
  write_file_atomically(path, prairielearn_json(page));
}

}  // namespace pt::grade
