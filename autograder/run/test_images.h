#pragma once
// The images a failing image test leaves (tests/support/image_test_files.h),
// taken into the report beside that test's failure.
//
// Who writes them, and why pt-grade still checks them: the test binary
// (under `pt-grade submission`, the kit's verifier: no student code) writes
// them into a fresh folder of the grader's own, given with --pt_image_dir and
// made writable for that run alone (Sandbox, RunRequest::output_dir). Where
// Landlock is missing, a worker running as the same user could write there
// too, and a binary graded in-process (`pt-grade run --binary`) holds the
// student's code: so once every process of the run is dead pt-grade takes
// only the file names it chose, each a regular file reached without
// following a link, a well-formed PNG (structure and checksums; never
// decoded here) of bounded size and dimensions, for a bounded number of
// tests, and keeps the bytes in memory; the folder is then removed.
#include <cstddef>
#include <string>
#include <vector>

namespace pt::grade {

struct TestImage {
  std::string name;     // one of kTestImageNames
  std::string caption;  // what it shows, for the page
  std::string png;      // the file's bytes
};

// The PNGs image_test_files.cpp writes, in the order the page shows them.
inline constexpr const char* kTestImageNames[] = {"render", "reference", "difference", "p_values"};
// One image: the verifier's are 256 x 192 pixels, blocks of one colour, a
// few KiB to a few tens of KiB.
inline constexpr size_t kMaxTestImageBytes = 96u << 10;
inline constexpr unsigned kMaxTestImageSide = 1024;
// Tests of one part whose images are kept (a part has at most three image
// tests; the rest of a hostile binary's failures keep only their message).
inline constexpr size_t kMaxImageTestsPerPart = 4;
// The flag that names the folder to a test binary (tests/support/test_main.cpp).
inline constexpr const char* kImageDirFlag = "--pt_image_dir=";

// "" when `bytes` is a PNG as a writer makes it (signature; IHDR first, 8-bit
// RGB or RGBA within kMaxTestImageSide; only IHDR, IDAT, IEND, each with its
// CRC; nothing after IEND); else what is wrong.
std::string png_problem(const std::string& bytes);

// The images of test `test` in `folder`/`test`/: each of kTestImageNames that
// is there and passes the checks above. What was refused goes to *refused
// (one line each, naming the file, not the test: a hidden test's name is not
// a student's to read); a missing file is not refused.
std::vector<TestImage> take_test_images(const std::string& folder, const std::string& test, std::string* refused);

}  // namespace pt::grade
