#pragma once
// The report a person reads: one self-contained HTML page
// per submission (no scripts, no outside files: images are inlined), with
//  * the score per part and per task;
//  * each failing test with its message, what the handout's grading table
//    says it checks and the handout section of its task; a failing image
//    test with its render, reference, difference and p-value images;
//  * the submission's renders of the library scenes beside the stored
//    reference images, a false-colour difference image and relMSE, with an
//    image whose error is far beyond what its sample count explains marked,
//    and the part it most likely points at;
//  * what the instructor should read: build times, the sandbox
//    layers that were active or missing, notes.
// Hidden tests are shown with their messages: the page is the instructor's
// (students see results.json on Gradescope, where hidden tests stay hidden).
#include <string>
#include <vector>

#include "report/handout_index.h"
#include "report/report.h"

namespace pt::grade {

struct RenderComparison {
  std::string scene;     // library name
  std::string purpose;   // one line: what the scene is for
  std::string settings;  // e.g. "256x192, 16 spp, depth 5"
  std::string student_png, reference_png, difference_png;  // files to inline ("" when missing)
  double relmse = -1, expected_relmse = -1, bound = -1;    // < 0: not measured
  std::vector<int> student_parts;  // parts of the submission this render used
  bool flagged = false;            // relmse above bound
  std::string suspect;             // "part 3 (direct illumination)": what the error most likely points at
  std::string error;               // the render failed: why
  std::string detail;              // the check's own account: every number it used
  double difference_scale = -1;    // what full red means in the difference image
};

struct HtmlReport {
  std::string title;  // e.g. the submission's file name
  const Report* report = nullptr;
  HandoutIndex handouts;
  std::vector<RenderComparison> renders;
  std::string renders_note;  // why there are none, or how they were made
};

// The page's text besides its images (the renders, whose number and sizes
// are the kit's scene library's) is at most this many bytes, whatever the
// submission does: the texts are capped (report_text.h), and halved until
// they fit.
inline constexpr size_t kMaxHtmlTextBytes = 2u << 20;

// A failing image test's images (test_images.h) are shown beside its
// message, until they take this many bytes of PNG on the page together; the
// tests after that say their images were left out.
inline constexpr size_t kMaxTestImageBytesOnPage = 1u << 20;

// Writes the page atomically; throws std::runtime_error naming the file.
void write_html_report(const std::string& path, const HtmlReport& page);

// Base64 of bytes, and of a file's bytes ("" when it cannot be read): for data: URIs.
std::string base64_text(const std::string& bytes);
std::string base64_file(const std::string& path);

}  // namespace pt::grade
