#include "io/image_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include <sys/stat.h>

#include <stb_image_write.h>
#include <tinyexr.h>

#include "render/limits.h"
#include "io/input_file.h"
#include "io/scene_loader.h"

namespace pt {

namespace {

// Writes the whole file or throws naming it and the reason. Every step is
// checked, fclose too: a full disk often shows only when the buffer is
// flushed. A regular file left incomplete is removed, so that no truncated
// image passes for a result (never anything else: /dev/full stays).
void write_file(const std::string& path, const unsigned char* data, size_t size, const char* what) {
  auto fail = [&](int err, bool remove) {
    if (remove) std::remove(path.c_str());
    throw std::runtime_error(path + ": cannot write " + what + ": " + std::strerror(err));
  };
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) fail(errno, false);
  struct stat st;
  const bool regular = fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode);
  if (std::fwrite(data, 1, size, f) != size || std::fflush(f) != 0) {
    int err = errno;
    std::fclose(f);
    fail(err, regular);
  }
  if (std::fclose(f) != 0) fail(errno, regular);
}

// The largest EXR a render of the largest allowed image makes (float RGBA,
// uncompressed) and then some for headers; anything larger is not ours.
constexpr uint64_t kMaxExrFileBytes = uint64_t(kMaxPixels) * 16 + (uint64_t(1) << 20);

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": " + why);
}

std::string take_exr_error(const char* err) {
  std::string msg = err ? err : "unknown error";
  FreeEXRErrorMessage(err);
  return msg;
}

}  // namespace

void write_exr(const std::string& path, const Image& image) {
  // What tinyexr's SaveEXR does, but to memory, so that the file write is ours
  // to check: float R, G, B planes stored in B, G, R order (what EXR viewers
  // expect), ZIP-compressed unless tiny.
  const size_t n = image.pixels.size();
  std::vector<float> planes[3];
  for (int c = 0; c < 3; ++c) {
    planes[c].resize(n);
    for (size_t i = 0; i < n; ++i) planes[c][i] = float(image.pixels[i][2 - c]);
  }
  float* plane_ptrs[3] = {planes[0].data(), planes[1].data(), planes[2].data()};
  EXRChannelInfo channels[3] = {};
  int pixel_types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
  for (int c = 0; c < 3; ++c) channels[c].name[0] = "BGR"[c];

  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = 3;
  header.channels = channels;
  header.pixel_types = pixel_types;
  header.requested_pixel_types = pixel_types;
  header.compression_type = image.width < 16 && image.height < 16 ? TINYEXR_COMPRESSIONTYPE_NONE
                                                                   : TINYEXR_COMPRESSIONTYPE_ZIP;
  EXRImage exr;
  InitEXRImage(&exr);
  exr.num_channels = 3;
  exr.images = reinterpret_cast<unsigned char**>(plane_ptrs);
  exr.width = image.width;
  exr.height = image.height;

  unsigned char* memory = nullptr;
  const char* err = nullptr;
  size_t size = SaveEXRImageToMemory(&exr, &header, &memory, &err);
  if (size == 0) throw std::runtime_error(path + ": cannot encode EXR: " + take_exr_error(err));
  std::unique_ptr<unsigned char, void (*)(void*)> owned(memory, &free);
  write_file(path, memory, size, "EXR");
}

Image read_exr(const std::string& path) {
  std::string file;
  try {
    file = read_input_file(path, kMaxExrFileBytes, "an EXR image");
  } catch (const SceneError& e) {
    throw std::runtime_error(e.what());
  }
  const auto* data = reinterpret_cast<const unsigned char*>(file.data());
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, data, file.size()) != TINYEXR_SUCCESS)
    refuse(path, "not an EXR image (no EXR signature)");
  if (version.multipart || version.non_image || version.tiled)
    refuse(path, "a multi-part, deep or tiled EXR (renders are single-part scanline images)");

  // tinyexr's LoadEXRFromMemory leaks the header when the pixels fail to
  // decode; here it is freed on every path.
  EXRHeader header;
  InitEXRHeader(&header);
  std::unique_ptr<EXRHeader, int (*)(EXRHeader*)> header_owner(&header, &FreeEXRHeader);
  const char* err = nullptr;
  if (ParseEXRHeaderFromMemory(&header, &version, data, file.size(), &err) != TINYEXR_SUCCESS)
    refuse(path, "cannot read EXR header: " + take_exr_error(err));
  // The size the header claims, checked before tinyexr allocates for it.
  const long long w = (long long)header.data_window.max_x - header.data_window.min_x + 1;
  const long long h = (long long)header.data_window.max_y - header.data_window.min_y + 1;
  if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide || w * h > kMaxPixels)
    refuse(path, "EXR of " + std::to_string(w) + "x" + std::to_string(h) + " pixels, more than a render may make (" +
                std::to_string(kMaxImageSide) + " a side, " + std::to_string(kMaxPixels) + " in all)");
  // Only the codecs a render may be saved with: tinyexr 1.0.1 (Debian 12)
  // reads past its buffer on damaged PIZ data (found by tests/fuzz; upstream
  // syoyo/tinyexr#176), and our writer never uses PIZ.
  const int codec = header.compression_type;
  if (codec != TINYEXR_COMPRESSIONTYPE_NONE && codec != TINYEXR_COMPRESSIONTYPE_RLE &&
      codec != TINYEXR_COMPRESSIONTYPE_ZIPS && codec != TINYEXR_COMPRESSIONTYPE_ZIP)
    refuse(path, "an EXR compressed with codec " + std::to_string(codec) +
                     " (PIZ and others are not read: save it uncompressed, RLE or ZIP)");
  // tinyexr sizes its block-offset table by the chunkCount attribute when
  // there is one (a 990-byte file asking for 2^31 blocks took 15 GB and
  // 28 s), and allocates every channel at full size before decoding.
  const int lines_per_block = codec == TINYEXR_COMPRESSIONTYPE_ZIP ? 16 : 1;
  const long long blocks = (h + lines_per_block - 1) / lines_per_block;
  if (header.chunk_count != 0 && header.chunk_count != blocks)
    refuse(path, "EXR chunkCount " + std::to_string(header.chunk_count) + " disagrees with the image's " +
                     std::to_string(blocks) + " blocks");
  if (header.num_channels > 4)
    refuse(path, "an EXR of " + std::to_string(header.num_channels) + " channels (renders have R, G, B and at most A)");
  int rgb[3] = {-1, -1, -1};
  for (int c = 0; c < header.num_channels; ++c) {
    for (int k = 0; k < 3; ++k)
      if (std::string(header.channels[c].name) == std::string(1, "RGB"[k])) rgb[k] = c;
    if (header.pixel_types[c] == TINYEXR_PIXELTYPE_UINT) refuse(path, "an EXR with integer channels");
    header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;  // half channels too
  }
  if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0) refuse(path, "an EXR without R, G and B channels");

  EXRImage exr;
  InitEXRImage(&exr);
  // On a decode error tinyexr frees the image itself (leaving the pointers),
  // but its planes only if num_channels is set, which it does on success.
  exr.num_channels = header.num_channels;
  if (LoadEXRImageFromMemory(&exr, &header, data, file.size(), &err) != TINYEXR_SUCCESS)
    refuse(path, "cannot read EXR: " + take_exr_error(err));
  std::unique_ptr<EXRImage, int (*)(EXRImage*)> image_owner(&exr, &FreeEXRImage);
  if (exr.width != w || exr.height != h || !exr.images) refuse(path, "cannot read EXR: inconsistent image size");
  Image img(exr.width, exr.height);
  const float* planes[3];
  for (int k = 0; k < 3; ++k) planes[k] = reinterpret_cast<const float*>(exr.images[rgb[k]]);
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = Spectrum(planes[0][i], planes[1][i], planes[2][i]);
  return img;
}

static double srgb_encode(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

void write_png(const std::string& path, const Image& image, double exposure) {
  double scale = std::exp2(exposure);
  std::vector<unsigned char> bytes(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double v = image.pixels[i][c] * scale;
      bytes[3 * i + c] = (unsigned char)std::lround(255.0 * srgb_encode(std::isfinite(v) ? v : 0.0));
    }
  // Encoded to memory: stbi_write_png ignores write errors.
  std::vector<unsigned char> png;
  auto append = [](void* out, void* data, int size) {
    auto* v = static_cast<std::vector<unsigned char>*>(out);
    auto* p = static_cast<unsigned char*>(data);
    v->insert(v->end(), p, p + size);
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, 3, bytes.data(), image.width * 3))
    throw std::runtime_error(path + ": cannot encode PNG");
  write_file(path, png.data(), png.size(), "PNG");
}

// A perceptually ordered blue-to-red ramp through cyan, green and yellow.

}  // namespace pt
