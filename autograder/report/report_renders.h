#pragma once
// The report's renders: the scene library rendered with
// the parts of a submission that earned points and the solution of the rest,
// each judged against its stored reference image.
//
// Who does what, and why it can be trusted:
//  * the kit's `pathtracer` (autograder/kit/CMakeLists.txt), linked with
//    the student's objects, runs in the sandbox and may write only a fresh
//    folder: it can make a wrong EXR, nothing else;
//  * the kit's `pt-library-check` (tools/library_check.cpp: the instructor's
//    build, no student code) reads that EXR and decides, with the library
//    test's own check (tests/support/reference_check.h: relMSE against the
//    error model of the stored reference, and region means, false-alarm
//    probability 1e-5 per image), whether the error is far beyond what the
//    sample count explains; it also draws the PNGs the page inlines;
//  * a flagged image with more than one student part in it is rendered again
//    with one student part at a time (`pathtracer_part<m>`): the parts whose
//    image is flagged alone are the suspects; with one part, that part.
// Renders never change the score: they are for the person reading the page.
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "report/html_report.h"
#include "run/grade_part.h"
#include "sandbox/sandbox.h"

namespace pt::grade {

// Runs a trusted build command (cmake) under a time limit; returns its exit
// status, with its output in *output (submission.cpp's build runner).
using BuildRunner = std::function<int(const std::vector<std::string>& argv, double seconds, std::string* output)>;

struct RenderJob {
  std::string kit;                 // the grading kit (its bin/pt-library-check, scenes/)
  std::string tree;                // the submission's build tree (tree/build is configured)
  // A new empty folder for each render's images, made by the grader where
  // the sandbox cannot create anything (work_area.h), handed to the sandbox's
  // user, and removed once its image is judged: nothing a render leaves is in
  // a path the grader uses next.
  ImageFolders folders;
  // True when the submission's files are over the grader's disk bound: a
  // render is then stopped, and its image judged missing.
  std::function<bool()> over_bound;
  // "" or what the bound did to a render (its output; stopped by over_bound).
  std::function<std::string(const std::string& output, bool stopped)> bound_note;
  std::string configure_parts;     // PT_PARTS_SUBMITTED as configured ("1;3")
  std::set<int> student_parts;     // the parts the renders take from the student
  std::map<int, std::string> part_names;  // n -> "part n (tasks/partn_....cpp)"
  double seconds = 60;             // builds and renders together
  double build_seconds = 50;       // one renderer's build
};

// Fills page.renders and page.renders_note; notes for the instructor go to
// *notes. Every render runs in `sandbox`.
void render_library(const RenderJob& job, const BuildRunner& build, Sandbox& sandbox, HtmlReport& page,
                    std::vector<std::string>* notes);

}  // namespace pt::grade
