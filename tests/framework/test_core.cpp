// Core helpers: frames, warps, the random generator, image files.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <unistd.h>

#include "core/frame.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "render/image.h"
#include "io/image_file.h"

namespace pt {
namespace {

TEST(Frame, IsOrthonormalAndRoundTrips) {
  Rng rng(1);
  std::vector<Vec3> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}};
  for (int i = 0; i < 1000; ++i) normals.push_back(sample_uniform_sphere(rng.uniform2()));
  for (const Vec3& n : normals) {
    Frame f = Frame::from_normal(n);
    EXPECT_NEAR(glm::dot(f.s, f.t), 0.0, 1e-12) << "n " << n;
    EXPECT_NEAR(glm::dot(f.s, f.n), 0.0, 1e-12) << "n " << n;
    EXPECT_NEAR(glm::length(f.s), 1.0, 1e-12) << "n " << n;
    EXPECT_NEAR(glm::length(f.t), 1.0, 1e-12) << "n " << n;
    EXPECT_NEAR(glm::dot(glm::cross(f.s, f.t), f.n), 1.0, 1e-12) << "right-handed, n " << n;
    Vec3 w(0.3, -0.5, 0.81);
    EXPECT_NEAR(glm::length(f.to_world(f.to_local(w)) - w), 0.0, 1e-12) << "n " << n;
    EXPECT_NEAR(f.to_local(n).z, 1.0, 1e-12);
  }
}

TEST(Warps, StayOnTheirDomainWithTheirPdf) {
  Rng rng(2);
  for (int i = 0; i < 10000; ++i) {
    Vec2 u = rng.uniform2();
    Vec3 h = sample_uniform_hemisphere(u), c = sample_cosine_hemisphere(u), s = sample_uniform_sphere(u);
    ASSERT_NEAR(glm::length(h), 1.0, 1e-12) << "u " << u;
    ASSERT_NEAR(glm::length(c), 1.0, 1e-12) << "u " << u;
    ASSERT_NEAR(glm::length(s), 1.0, 1e-12) << "u " << u;
    ASSERT_GE(h.z, 0.0);
    ASSERT_GE(c.z, 0.0);
    ASSERT_DOUBLE_EQ(pdf_uniform_hemisphere(h), 1.0 / (2.0 * kPi));
    ASSERT_DOUBLE_EQ(pdf_cosine_hemisphere(c), c.z / kPi);
  }
  EXPECT_EQ(pdf_uniform_hemisphere({0, 0, -1}), 0.0);
  EXPECT_EQ(pdf_cosine_hemisphere({0, 0, -1}), 0.0);
}

TEST(Rng, UniformInUnitIntervalAndPixelStreamsDiffer) {
  Rng rng(3);
  double sum = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  // Mean of n uniforms has sd 1/sqrt(12 n) ~ 0.0009: 5 sd is a 1e-6 false alarm.
  EXPECT_NEAR(sum / n, 0.5, 5.0 / std::sqrt(12.0 * n));
  std::set<double> firsts;
  for (uint32_t x = 0; x < 64; ++x)
    for (uint32_t y = 0; y < 64; ++y) firsts.insert(Rng::for_pixel(9, x, y).uniform());
  EXPECT_GT(firsts.size(), 4090u) << "neighbouring pixels must not share streams";
  EXPECT_EQ(Rng::for_pixel(9, 5, 6).uniform(), Rng::for_pixel(9, 5, 6).uniform());
}

TEST(ImageFiles, ExrRoundTripsAndPngWrites) {
  Image img(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) img.at(x, y) = Spectrum(x * 0.5, y * 2.0, 1e3 + x);
  auto dir = std::filesystem::temp_directory_path() / ("pt_image_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_exr((dir / "a.exr").string(), img);
  Image back = read_exr((dir / "a.exr").string());
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  for (size_t i = 0; i < img.pixels.size(); ++i)
    EXPECT_NEAR(glm::length(back.pixels[i] - img.pixels[i]), 0.0, 1e-3 * glm::length(img.pixels[i]));
  write_png((dir / "a.png").string(), img);
  EXPECT_GT(std::filesystem::file_size(dir / "a.png"), 0u);
  EXPECT_THROW(read_exr((dir / "missing.exr").string()), std::runtime_error);
  std::filesystem::remove_all(dir);
}

// A write that fails is an error naming the file and the reason, never a
// silent success (stb and tinyexr do not check their writes).
TEST(ImageFiles, WriteErrorsNameTheFileAndTheReason) {
  Image img(4, 4, Spectrum(0.5));
  using Writer = void (*)(const std::string&, const Image&);
  const Writer writers[] = {[](const std::string& p, const Image& i) { write_png(p, i); }, &write_exr};
  for (Writer writer : writers) {
    try {
      writer("/dev/full", img);
      ADD_FAILURE() << "writing to /dev/full succeeded";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("/dev/full: cannot write"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
    }
    EXPECT_THROW(writer("/nonexistent_dir_pt/a.png", img), std::runtime_error);
  }
}

// read_exr refuses, before decoding, a file that is not an EXR and a header
// that claims more pixels than any render may have (tinyexr would allocate
// for it).
TEST(ImageFiles, ReadExrRefusesWhatIsNotAnImageOfOurs) {
  auto dir = std::filesystem::temp_directory_path() / ("pt_image_refuse_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Image img(4, 4, Spectrum(0.5));
  write_png((dir / "a.png").string(), img);
  try {
    read_exr((dir / "a.png").string());
    ADD_FAILURE() << "read a PNG as an EXR";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a.png: not an EXR image"), std::string::npos) << e.what();
  }
  // An uncompressed 4x4 EXR whose dataWindow (xMin yMin xMax yMax) is made
  // to claim 100000 x 100000 pixels.
  write_exr((dir / "a.exr").string(), img);
  std::string bytes;
  {
    std::ifstream in(dir / "a.exr", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string key("dataWindow\0box2i\0", 17);
  size_t at = bytes.find(key);
  ASSERT_NE(at, std::string::npos);
  int32_t box[4] = {0, 0, 99999, 99999};
  bytes.replace(at + key.size() + 4, sizeof box, reinterpret_cast<const char*>(box), sizeof box);
  std::ofstream(dir / "huge.exr", std::ios::binary) << bytes;
  try {
    read_exr((dir / "huge.exr").string());
    ADD_FAILURE() << "read an EXR claiming 10^10 pixels";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("huge.exr: EXR of 100000x100000 pixels"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(ImageCompare, ZeroForIdenticalAndScalesWithError) {
  Image a(4, 4, Spectrum(0.5)), b(4, 4, Spectrum(0.5));
  EXPECT_EQ(compare_images(a, b).rmse, 0.0);
  b.at(1, 1) = Spectrum(1.5);
  // One pixel of 16, all three channels off by 1: RMSE = sqrt(3 / 48) = 0.25.
  EXPECT_NEAR(compare_images(b, a).rmse, 0.25, 1e-12);
}

}  // namespace
}  // namespace pt
