#pragma once
// PrairieLearn's results.json (its external grader reads
// /grade/results/results.json; prairielearn/README.md): the same grading as
// Gradescope's results.json (report.h) in PrairieLearn's format:
//   gradable  false only when the submission as a whole could not be graded
//             (Report::ungradable: refused before anything was built, or the
//             grader failed): PrairieLearn then counts no attempt; a part
//             that does not compile is graded, and scores 0;
//   score     points earned / points possible, in [0, 1];
//   message   the score in one line, or why it could not be graded;
//   output    the report's notes and what each render showed;
//   images    each library scene rendered with the submission beside its
//             stored reference (data: URLs), within kMaxImageBytes: the
//             renders past it are left out, and the output says so;
//   tests     every graded test: name, description (what the handout's
//             grading table says it checks, and the task's section), points,
//             max_points, message, output. A hidden test is shown by its task
//             and points only (PrairieLearn has no "after the deadline"):
//             students see all of this file that PrairieLearn renders.
// The whole file is at most kMaxResultsBytes (PrairieLearn's limit is 1 MB).
#include <cstddef>
#include <string>

#include "report/html_report.h"

namespace pt::grade {

// The data: URLs of the images together; the text gets the rest.
inline constexpr size_t kMaxImageBytes = 600000;

// The document as text (what write_prairielearn_json writes).
std::string prairielearn_json(const HtmlReport& page);

// Writes it atomically; throws std::runtime_error naming the file.
void write_prairielearn_json(const std::string& path, const HtmlReport& page);

}  // namespace pt::grade
