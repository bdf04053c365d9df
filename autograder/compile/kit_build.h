#pragma once
// Running the grading kit's build on a submission's task files (submission.h,
// step 4). The compiler, the assembler and the linker are trusted programs
// working on hostile input, as the grader's own user (root on Gradescope):
// `asm(".incbin \"FILE\"")` makes the assembler copy any file it can read into
// the program, and no scan of the source finds every spelling of it (the
// preprocessor can paste the directive together). So each build step runs
//
//  - confined by Landlock where the kernel offers it: it reads only the
//    system (/usr and the library folders, /etc/ld.so.cache) and the build
//    tree, writes only the tree, executes only the system's programs and the
//    kit's bin/ (autograder/hostile/incbin_pasted);
//  - under a wall-clock limit for its whole process group (coreutils
//    `timeout`), a 4 GiB address-space limit and a 512 MiB file-size limit
//    per process (util-linux `prlimit`) (autograder/hostile/compile_time_bomb,
//    build_fill; the tree's whole size is work_area.h's);
//  - sent SIGTERM when the grader dies, which `timeout` passes on to the
//    compiler: a grader killed from outside leaves no build running
//    (autograder/hostile/grader_killed_building);
//  - in an IPC namespace of its own where the kernel allows one;
//  - with at most 1 MiB of its output kept (and the kit's compiler stops
//    after 20 errors), so that an error flood costs the grader no memory
//    (autograder/hostile/error_flood).
#include <functional>
#include <string>
#include <vector>

namespace pt::grade {

class KitBuild {
 public:
  // `tree`: the submission's copy of the kit. `confine`: Landlock where the
  // kernel offers it (false: --no-sandbox, --sandbox-without landlock).
  KitBuild(std::string tree, bool confine);
  ~KitBuild();
  KitBuild(const KitBuild&) = delete;
  KitBuild& operator=(const KitBuild&) = delete;

  // "" when Landlock confines every build step; else why it does not.
  const std::string& unconfined_reason() const { return unconfined_; }

  // Runs one build step (cmake); standard error joins standard output, of
  // which the first 1 MiB is kept. Exit status 124 or 137: the time ran out.
  int run(const std::vector<std::string>& argv, double seconds, std::string* output) const;

  // A bound no limit enforces (the work area's size on disk): the build is
  // killed when this says so.
  void stop_when(std::function<bool()> over) { over_ = std::move(over); }

 private:
  std::string tree_;
  std::function<bool()> over_;
  int ruleset_ = -1;
  std::string unconfined_;
};

}  // namespace pt::grade
