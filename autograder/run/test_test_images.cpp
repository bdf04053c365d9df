// A failing image test's images reach the report (test_images.h) only as
// what pt-grade chose to take: its own file names, regular files reached
// without a link, well-formed PNGs within their bounds; and the page shows
// them within its own bound, results.json not at all; grade_binary gives each
// run its folder and rewrites each message to point at the report.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image_file.h"
#include "report/html_report.h"
#include "report/report.h"
#include "report/report_text.h"
#include "run/grade_part.h"
#include "run/test_images.h"

namespace pt::grade {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A PNG as the verifier writes one (io/image_file.h), `w` x `h`; `noisy`
// pixels compress little.
std::string png_bytes(const fs::path& dir, int w, int h, bool noisy = false) {
  Image img(w, h);
  uint32_t x = 12345;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    x = x * 1664525u + 1013904223u;
    img.pixels[i] = noisy ? Spectrum((x >> 8) % 256 / 255.0, (x >> 16) % 256 / 255.0, (x >> 24) / 255.0)
                          : Spectrum(double(i % 7) / 7.0, 0.5, 0.25);
  }
  const fs::path p = dir / "made.png";
  write_png(p.string(), img);
  std::string bytes = read_all(p);
  fs::remove(p);
  return bytes;
}

void write_bytes(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

class TestImages : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::path(::testing::TempDir()) / ("pt_test_images_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "ImageP3.Scene");
    png = png_bytes(root, 256, 192);
  }
  void TearDown() override { fs::remove_all(root); }

  // grade_binary on the helper binary whose six image tests all fail, each
  // writing its images into the folders `folders` makes.
  PartResult grade_failing_image_tests(const ImageFolders& folders) {
    PartManifest tests;
    for (int k = 0; k < 6; ++k) tests.push_back({"ImageP9.T" + std::to_string(k), "P9T1", 1, false, false});
    SandboxOptions options;
    options.confine = false;
    Sandbox sandbox(options);
    return grade_binary(9, PT_FAILING_IMAGE_TESTS, tests, GradeLimits(), sandbox, "", Redactor(), "", &folders);
  }

  fs::path root;
  std::string png;
};

TEST_F(TestImages, AWritersPngPassesAndEveryDamageIsNamed) {
  ASSERT_EQ(png_problem(png), "");
  EXPECT_NE(png_problem("GIF89a" + png.substr(6)).find("not a PNG"), std::string::npos);
  EXPECT_NE(png_problem(png + "trailing").find("after IEND"), std::string::npos);
  EXPECT_NE(png_problem(png.substr(0, png.size() - 12)).find("no IEND"), std::string::npos);
  EXPECT_NE(png_problem(png.substr(0, png.size() - 5)).find("cut short"), std::string::npos);
  std::string flipped = png;
  flipped[png.size() / 2] ^= 0x10;  // inside the image data
  EXPECT_NE(png_problem(flipped).find("CRC"), std::string::npos);
  EXPECT_NE(png_problem(png_bytes(root, 2000, 4)).find("beyond"), std::string::npos);
  std::string longer = png;
  longer[8 + 3] = 100;  // IHDR's length
  EXPECT_NE(png_problem(longer), "");
}

TEST_F(TestImages, TheFourImagesAreTakenInOrderWithCaptions) {
  for (const char* n : kTestImageNames) write_bytes(root / "ImageP3.Scene" / (std::string(n) + ".png"), png);
  write_bytes(root / "ImageP3.Scene" / "render.exr", "not taken");
  write_bytes(root / "ImageP3.Scene" / "extra.png", png);
  std::string refused;
  const auto images = take_test_images(root.string(), "ImageP3.Scene", &refused);
  EXPECT_EQ(refused, "");
  ASSERT_EQ(images.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(images[i].name, kTestImageNames[i]);
    EXPECT_EQ(images[i].png, png);
    EXPECT_FALSE(images[i].caption.empty());
  }
  // No folder for a test: nothing, and nothing refused.
  EXPECT_TRUE(take_test_images(root.string(), "Other.Test", &refused).empty());
  EXPECT_EQ(refused, "");
}

// What a writer other than the verifier could leave: each refused, named, and
// the grader neither follows a link nor waits on a FIFO.
TEST_F(TestImages, PlantedFilesAreRefused) {
  const fs::path dir = root / "ImageP3.Scene";
  write_bytes(root / "elsewhere.png", png);
  fs::create_symlink(root / "elsewhere.png", dir / "render.png");
  ASSERT_EQ(::mkfifo((dir / "reference.png").c_str(), 0600), 0);
  write_bytes(dir / "difference.png", png + std::string(kMaxTestImageBytes, '\0'));
  write_bytes(dir / "p_values.png", "<svg onload=alert(1)>");
  std::string refused;
  EXPECT_TRUE(take_test_images(root.string(), "ImageP3.Scene", &refused).empty());
  for (const char* n : kTestImageNames) EXPECT_NE(refused.find(std::string(n) + ".png: "), std::string::npos) << refused;
  EXPECT_NE(refused.find("over the bound"), std::string::npos);
  EXPECT_NE(refused.find("not a PNG"), std::string::npos);
  // The test's folder a link to one full of good images: not followed.
  fs::create_directories(root / "real");
  write_bytes(root / "real" / "render.png", png);
  fs::create_directory_symlink(root / "real", root / "Linked.Test");
  refused.clear();
  EXPECT_TRUE(take_test_images(root.string(), "Linked.Test", &refused).empty());
  EXPECT_NE(refused.find("not a folder"), std::string::npos);
  // Names the grader did not choose.
  EXPECT_TRUE(take_test_images(root.string(), "../real", &refused).empty());
  EXPECT_TRUE(take_test_images(root.string(), "..", &refused).empty());
}

// Twenty failing tests, each with four images at the bound: the page shows
// the first until kMaxTestImageBytesOnPage and says the rest were left out;
// results.json carries no image and stays within its bound.
TEST_F(TestImages, ThePageBoundsThemAndResultsJsonHasNone) {
  const std::string big = png_bytes(root, 128, 96, true);
  ASSERT_GT(big.size(), 20000u);
  Report report;
  PartResult part;
  part.part = 3;
  for (int i = 0; i < 20; ++i) {
    TestResult t;
    t.test = {"ImageP3.Scene" + std::to_string(i), "P3T4", 1, false, false};
    t.status = TestResult::Status::Failed;
    t.message = "worst region cell (column 1, row 0) of the 4x4 grid, test " + std::to_string(i);
    for (const char* n : kTestImageNames) t.images.push_back({n, std::string("caption of ") + n, big});
    part.tests.push_back(t);
  }
  report.parts.push_back(part);
  report.complete = true;
  HtmlReport page;
  page.title = "images";
  page.report = &report;
  const fs::path html = root / "report.html", json = root / "results.json";
  write_html_report(html.string(), page);
  write_results_json(json.string(), report);
  const std::string text = read_all(html);
  size_t shown = 0;
  for (size_t at = 0; (at = text.find("data:image/png;base64,", at)) != std::string::npos; ++at) ++shown;
  const size_t per_test = 4 * big.size();
  EXPECT_EQ(shown, 4 * (kMaxTestImageBytesOnPage / per_test));
  EXPECT_GT(shown, 0u);
  EXPECT_LT(shown, 4u * 20u);
  EXPECT_NE(text.find("caption of p_values"), std::string::npos);
  EXPECT_NE(text.find("its images are left out"), std::string::npos);
  const std::string results = read_all(json);
  EXPECT_LE(results.size(), kMaxResultsBytes);
  EXPECT_EQ(results.find("base64"), std::string::npos);
  EXPECT_EQ(results.find(base64_text(big).substr(0, 64)), std::string::npos);
}

// grade_binary with a binary whose six image tests all fail, each writing its
// images: the run gets a folder of its own, named with --pt_image_dir and
// removed after; the images of the first four failing tests are taken (T0's
// file that is not a PNG refused and named), the two beyond the bound noted;
// every message names the report or says the images were not kept, never
// the folder.
TEST_F(TestImages, GradeBinaryTakesTheImagesOfFailingTests) {
  std::vector<std::string> made, discarded;
  const ImageFolders folders{[&](std::string*) {
                               const fs::path d = root / ("run-" + std::to_string(made.size() + 1));
                               fs::create_directory(d);
                               made.push_back(d.string());
                               return d.string();
                             },
                             [&](const std::string& d) {
                               discarded.push_back(d);
                               fs::remove_all(d);
                             }};
  const PartResult r = grade_failing_image_tests(folders);
  ASSERT_EQ(r.tests.size(), 6u);
  ASSERT_EQ(made.size(), 1u);
  EXPECT_EQ(discarded, made);
  EXPECT_FALSE(fs::exists(made[0]));
  const size_t expected[] = {3, 4, 4, 4, 0, 0};
  for (int k = 0; k < 6; ++k) {
    const TestResult& t = r.tests[k];
    EXPECT_EQ(t.status, TestResult::Status::Failed) << t.test.name;
    EXPECT_EQ(t.images.size(), expected[k]) << t.test.name;
    EXPECT_EQ(t.message.find(made[0]), std::string::npos) << t.message;
    EXPECT_NE(t.message.find("worst region"), std::string::npos) << t.message;
    EXPECT_NE(t.message.find(k < 4 ? "images in the grader's HTML report, beside this message: render.png"
                                   : "images in a folder the grader did not keep"),
              std::string::npos)
        << t.message;
  }
  std::string notes;
  for (const auto& n : r.notes) notes += n + "\n";
  EXPECT_NE(notes.find("images of the failing ImageP9.T0 refused:\np_values.png: not a PNG"), std::string::npos) << notes;
  EXPECT_NE(notes.find("the images of 2 more failing test(s) were not kept"), std::string::npos) << notes;
}


// The student's own check (check-submission) keeps the folder: no image is
// taken into the result, each message still names its folder, and the files
// are there to open.
TEST_F(TestImages, KeptFoldersStayWhereTheMessagesNameThem) {
  std::vector<std::string> made;
  const ImageFolders folders{[&](std::string*) {
                               const fs::path d = root / ("kept-" + std::to_string(made.size() + 1));
                               fs::create_directory(d);
                               made.push_back(d.string());
                               return d.string();
                             },
                             [](const std::string&) {}, true};
  const PartResult r = grade_failing_image_tests(folders);
  ASSERT_EQ(r.tests.size(), 6u);
  ASSERT_EQ(made.size(), 1u);
  for (const TestResult& t : r.tests) {
    EXPECT_TRUE(t.images.empty()) << t.test.name;
    EXPECT_NE(t.message.find(made[0] + "/" + t.test.name + "/"), std::string::npos) << t.message;
  }
  EXPECT_TRUE(fs::exists(fs::path(made[0]) / "ImageP9.T1" / "render.png"));
}

}  // namespace
}  // namespace pt::grade
