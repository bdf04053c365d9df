#include "io/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "io/scene_loader.h"

namespace fs = std::filesystem;

namespace pt {

std::string format_bytes(uint64_t bytes) {
  char buf[32];
  const double b = double(bytes);
  if (bytes < 1024) std::snprintf(buf, sizeof buf, "%llu bytes", (unsigned long long)bytes);
  else if (bytes < (1u << 20)) std::snprintf(buf, sizeof buf, "%.3g KiB", b / 1024);
  else if (bytes < (1u << 30)) std::snprintf(buf, sizeof buf, "%.3g MiB", b / (1 << 20));
  else std::snprintf(buf, sizeof buf, "%.3g GiB", b / (1 << 30));
  return buf;
}

void check_input_path(const std::string& path, const char* what) {
  // status() follows symlinks; a loop or a dangling link is an error here,
  // never an exception of another type.
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) throw SceneError(path + ": cannot open: " + ec.message());
  if (!fs::exists(st)) throw SceneError(path + ": cannot open: no such file");
  if (fs::is_directory(st)) throw SceneError(path + ": is a directory, not " + what);
  if (!fs::is_regular_file(st)) throw SceneError(path + ": is not a regular file (" + what + " must be one)");
}

std::string read_input_file(const std::string& path, uint64_t max_bytes, const char* what) {
  const std::string bound = std::string("larger than the ") + format_bytes(max_bytes) + " " + what + " may have";
  check_input_path(path, what);
  std::error_code ec;
  uint64_t size = fs::file_size(path, ec);
  if (!ec && size > max_bytes) throw SceneError(path + ": " + format_bytes(size) + ", " + bound);

  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw SceneError(path + ": cannot open: " + std::strerror(errno));
  std::string text;
  text.reserve(ec ? 0 : size_t(size));
  char buf[1 << 16];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, f.get())) > 0;) {
    if (text.size() + n > max_bytes) throw SceneError(path + ": " + bound);
    text.append(buf, n);
  }
  if (std::ferror(f.get())) throw SceneError(path + ": cannot read: " + std::strerror(errno));
  return text;
}

}  // namespace pt
