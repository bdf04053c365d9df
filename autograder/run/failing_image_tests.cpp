// A test binary as pt-grade sees one (the records of tests/support/test_main.cpp),
// whose six tests ImageP9.T0 ... T5 all fail as an image test does: each
// writes render.png, reference.png, difference.png and p_values.png into
// <--pt_image_dir>/<test>/ and names that folder in its message. T0's
// p_values.png is not a PNG. For autograder:TestImages.GradeBinary*.
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/image_file.h"

int main(int argc, char** argv) {
  char key[33] = {};
  for (size_t got = 0; got < 32;) {
    const ssize_t n = ::read(4, key + got, 32 - got);
    if (n <= 0) return 2;
    got += size_t(n);
  }
  std::string dir;
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--pt_image_dir=", 15) == 0) dir = argv[i] + 15;
  FILE* channel = ::fdopen(3, "w");
  if (!channel) return 2;
  auto record = [&](const std::string& body) { std::fprintf(channel, "{%s,\"k\":\"%s\"}\n", body.c_str(), key); };
  record("\"hello\":{\"threads\":1}");
  pt::Image img(32, 24);
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = pt::Spectrum(double(i % 5) / 5.0);
  for (int k = 0; k < 6; ++k) {
    const std::string name = "ImageP9.T" + std::to_string(k), folder = dir + "/" + name;
    record("\"start\":\"" + name + "\"");
    std::filesystem::create_directories(folder);
    for (const char* png : {"render", "reference", "difference", "p_values"}) pt::write_png(folder + "/" + png + ".png", img);
    if (k == 0) std::ofstream(folder + "/p_values.png") << "not a PNG";
    record("\"end\":\"" + name + "\",\"passed\":false,\"skipped\":false,\"seconds\":0.1,\"message\":\"DIFFERS; worst region "
           "the whole image; images in " + folder + "/: render.png, reference.png\"");
  }
  record("\"done\":1");
  std::fclose(channel);
  return 1;
}
