#pragma once
// Where `pt-grade submission` builds and renders a submission (submission.h,
// steps 4 and 6): one fresh folder per submission, bounded in size, holding
//
//   tree/      the kit's copy and the build (mode 0700: the grader's alone)
//   renders/   mode 0711, the grader's: the sandbox can pass through it but
//              never create anything in it, so each render's own folder,
//              made here fresh by the grader, is never a path the code under
//              test could have planted (a file, or a link to results.json)
//
// The bound (kDiskBytes, 512 MiB) is a tmpfs mounted on the folder in a mount
// namespace of the grader's own, where the grader may make one (root, or
// CAP_SYS_ADMIN): the kernel refuses the byte past it, and the mount dies
// with the grader however it ends. Elsewhere the folder is on disk and
// exceeded() is what stops a build or a render, checked while it runs.
// Everything the build and the renderer write also has a per-file limit
// (RLIMIT_FSIZE).
#include <cstdint>
#include <string>

namespace pt::grade {

inline constexpr uint64_t kDiskBytes = 512ull << 20;

class WorkArea {
 public:
  // A fresh folder in `parent` (created if missing), on the bounded tmpfs
  // unless `no_tmpfs` says why not (--sandbox-without namespaces, to test the
  // fallback; --keep-work, since the tmpfs ends with the grader). Throws
  // std::runtime_error when no folder can be made.
  WorkArea(const std::string& parent, const std::string& no_tmpfs);
  ~WorkArea();  // removes it all, unless kept
  WorkArea(const WorkArea&) = delete;
  WorkArea& operator=(const WorkArea&) = delete;

  const std::string& root() const { return root_; }
  std::string tree() const { return root_ + "/tree"; }
  // "" when the tmpfs holds the bound; else why not (for the report's notes).
  const std::string& unbounded_reason() const { return unbounded_; }
  // Bytes in the folder (the tmpfs's use, or a walk of the folder on disk).
  uint64_t used() const;
  bool exceeded() const { return used() >= kDiskBytes; }

  // A new empty folder in renders/ for one render, mode 0700 (the sandbox
  // hands it to its user: Sandbox::run, through a descriptor opened without
  // following links). Returns "" when it cannot be made (*error says why).
  std::string fresh_render_folder(std::string* error);

  void keep() { keep_ = true; }
  // Removes everything now (the destructor's work), so that a caller can say
  // whether it succeeded.
  void remove();

 private:
  std::string root_, unbounded_;
  bool mounted_ = false, keep_ = false, removed_ = false;
  int renders_ = 0;
};

// A sentence for the report when the bound stopped a build or a render
// (`stopped`, where exceeded() is what enforces it) or `text` (its output)
// shows a write refused by it; "" otherwise.
std::string disk_bound_note(const std::string& text, const WorkArea& area, bool stopped = false);

}  // namespace pt::grade
