#include "run/test_images.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>

#include "process/launcher.h"  // Fd

namespace pt::grade {

namespace {

uint32_t crc32(const unsigned char* data, size_t n) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

uint32_t big_endian(const unsigned char* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

const char* caption_of(const std::string& name) {
  if (name == "render") return "the test's render (mean of its renders)";
  if (name == "reference") return "the stored reference, block-averaged to the test's size";
  if (name == "difference") return "|difference| of illuminance, false colour to its 99th percentile";
  return "smallest p of each cell of the finest grid: black p = 1, white at the threshold, red below it";
}

}  // namespace

std::string png_problem(const std::string& bytes) {
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const size_t n = bytes.size();
  if (n < 8 || std::memcmp(p, signature, 8) != 0) return "not a PNG (no PNG signature)";
  bool ihdr = false, idat = false;
  for (size_t at = 8; at < n;) {
    if (n - at < 12) return "a chunk cut short";
    const uint32_t length = big_endian(p + at);
    if (length > n - at - 12) return "a chunk longer than the file";
    const std::string type(reinterpret_cast<const char*>(p + at + 4), 4);
    if (crc32(p + at + 4, length + 4) != big_endian(p + at + 8 + length)) return "a " + type + " chunk with a wrong CRC";
    const unsigned char* data = p + at + 8;
    if (!ihdr) {
      if (type != "IHDR" || length != 13) return "the first chunk is not an IHDR";
      const uint32_t w = big_endian(data), h = big_endian(data + 4);
      if (w == 0 || h == 0 || w > kMaxTestImageSide || h > kMaxTestImageSide)
        return "dimensions " + std::to_string(w) + "x" + std::to_string(h) + " beyond " +
               std::to_string(kMaxTestImageSide) + " pixels a side";
      if (data[8] != 8 || (data[9] != 2 && data[9] != 6) || data[10] != 0 || data[11] != 0 || data[12] != 0)
        return "not an 8-bit, non-interlaced RGB or RGBA PNG";
      ihdr = true;
    } else if (type == "IDAT") {
      idat = true;
    } else if (type == "IEND") {
      if (!idat) return "no image data";
      if (length != 0 || at + 12 != n) return "bytes after IEND";
      return "";
    } else {
      return "a chunk of type other than IHDR, IDAT or IEND";
    }
    at += 12 + length;
  }
  return "no IEND chunk";
}

std::vector<TestImage> take_test_images(const std::string& folder, const std::string& test, std::string* refused) {
  std::vector<TestImage> images;
  if (test.empty() || test.find('/') != std::string::npos || test[0] == '.') return images;
  // Each step opened without following a link: the folder is the grader's,
  // what is in it may have been planted.
  const Fd top(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
  if (top.get() < 0) return images;
  const Fd dir(::openat(top.get(), test.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
  if (dir.get() < 0) {
    if (errno != ENOENT) *refused += "its folder: not a folder (" + std::string(std::strerror(errno)) + ")\n";
    return images;
  }
  for (const char* name : kTestImageNames) {
    const std::string file = std::string(name) + ".png";
    // O_NONBLOCK: a FIFO planted under this name must not hang the grader.
    const Fd f(::openat(dir.get(), file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC));
    if (f.get() < 0) {
      if (errno != ENOENT) *refused += file + ": " + std::strerror(errno) + "\n";
      continue;
    }
    struct stat st{};
    if (::fstat(f.get(), &st) != 0 || !S_ISREG(st.st_mode)) {
      *refused += file + ": not a regular file\n";
      continue;
    }
    if (uint64_t(st.st_size) > kMaxTestImageBytes) {
      *refused += file + ": " + std::to_string(st.st_size) + " bytes, over the bound of " +
                  std::to_string(kMaxTestImageBytes) + "\n";
      continue;
    }
    std::string bytes(size_t(st.st_size), '\0');
    size_t got = 0;
    for (ssize_t r; got < bytes.size() && (r = ::read(f.get(), bytes.data() + got, bytes.size() - got)) != 0;) {
      if (r < 0 && errno == EINTR) continue;
      if (r < 0) break;
      got += size_t(r);
    }
    bytes.resize(got);
    if (const std::string why = png_problem(bytes); !why.empty()) {
      *refused += file + ": " + why + "\n";
      continue;
    }
    images.push_back({name, caption_of(name), std::move(bytes)});
  }
  return images;
}

}  // namespace pt::grade
