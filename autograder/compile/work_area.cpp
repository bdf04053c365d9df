#include "compile/work_area.h"

#include <sched.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace pt::grade {

namespace {

namespace fs = std::filesystem;

std::string errno_text(const std::string& what) { return what + ": " + std::strerror(errno); }

// A tmpfs of kDiskBytes on `dir`, in a mount namespace of this process's own
// (made private, so the mount is seen by no one else and ends with it).
std::string mount_bounded(const std::string& dir) {
  if (::unshare(CLONE_NEWNS) != 0) return errno_text("no mount namespace of its own");
  if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return errno_text("mounts not private");
  const std::string options = "size=" + std::to_string(kDiskBytes) + ",mode=0711";
  if (::mount("pt-submission", dir.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, options.c_str()) != 0)
    return errno_text("no tmpfs");
  return "";
}

}  // namespace

WorkArea::WorkArea(const std::string& parent, const std::string& no_tmpfs) {
  std::error_code ec;
  fs::create_directories(parent, ec);
  // No link anywhere in the paths below: each is then opened without
  // following any (fresh_render_folder, the sandbox's chown).
  const fs::path real = fs::canonical(parent, ec);
  if (ec) throw std::runtime_error("cannot use " + parent + " for the build: " + ec.message());
  std::string pattern = (real / "pt-submission-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error(errno_text("cannot create a folder in " + real.string()));
  root_ = pattern;
  unbounded_ = no_tmpfs.empty() ? mount_bounded(root_) : no_tmpfs;
  mounted_ = unbounded_.empty();
  // The sandbox's user passes through to its own render folder, and sees nothing else.
  if (::chmod(root_.c_str(), 0711) != 0 || ::mkdir(tree().c_str(), 0700) != 0 ||
      ::mkdir((root_ + "/renders").c_str(), 0711) != 0 || ::chmod((root_ + "/renders").c_str(), 0711) != 0) {
    const std::string why = errno_text("cannot prepare " + root_);
    remove();
    throw std::runtime_error(why);
  }
}

WorkArea::~WorkArea() {
  if (!keep_) remove();
}

void WorkArea::remove() {
  if (removed_ || root_.empty()) return;
  removed_ = true;
  std::error_code ec;
  // Every process that wrote here is dead (the sandbox and the build see to
  // it), so nothing can swap a path while this walks; remove_all does not
  // follow links.
  for (const auto& e : fs::directory_iterator(root_, ec)) fs::remove_all(e.path(), ec);
  if (mounted_) ::umount2(root_.c_str(), MNT_DETACH);
  fs::remove(root_, ec);
}

uint64_t WorkArea::used() const {
  if (mounted_) {
    struct statvfs s{};
    if (::statvfs(root_.c_str(), &s) != 0) return 0;
    return (uint64_t(s.f_blocks) - s.f_bfree) * s.f_frsize;
  }
  uint64_t bytes = 0;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(root_, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    struct stat st{};
    if (::lstat(it->path().c_str(), &st) == 0) bytes += uint64_t(st.st_blocks) * 512;
  }
  return bytes;
}

std::string WorkArea::fresh_render_folder(std::string* error) {
  const std::string dir = root_ + "/renders/run-" + std::to_string(++renders_);
  if (::mkdir(dir.c_str(), 0700) != 0) {
    *error = errno_text("cannot make " + dir);
    return "";
  }
  return dir;
}

std::string disk_bound_note(const std::string& text, const WorkArea& area, bool stopped) {
  const bool refused = stopped || text.find("No space left on device") != std::string::npos ||
                       text.find("File size limit exceeded") != std::string::npos ||
                       text.find("File too large") != std::string::npos;
  if (!refused && !area.exceeded()) return "";
  return "the submission's files reached the grader's bound on disk: " + std::to_string(kDiskBytes >> 20) +
         " MiB for the build and the renders together (and per file)";
}

}  // namespace pt::grade
