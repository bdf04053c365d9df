#pragma once
// Running code under test with the least privilege and the tightest limits
// this machine allows (autograder/README.md has the threat model):
//
//   namespaces   PID (every descendant dies with the run), mount (a private
//                tmpfs working directory, a /proc that shows only the run),
//                IPC (System V objects and message queues die with the run),
//                and a user namespace when the grader is not root
//   user         an unprivileged account (default nobody) when the grader is root
//   session      its own, with no terminal
//   limits       address space, CPU time, file size, open files, processes
//   landlock     reads only the system and the given paths, writes only its
//                working directory, executes only itself, no TCP, no signals out
//   seccomp      an allowlist of system calls: no fork, exec, ptrace,
//                sockets or IPC objects; signals only to itself
//   output       through a pipe, only the head and tail of it kept
//
// Each layer is probed once; what this machine does not offer is left out and
// named in layers_missing(), never silently assumed. Linux only (sandbox.cpp);
// a build without it (PT_SANDBOX off: macOS) has unconfined.cpp, a plain
// child process with every layer missing, for the student's own check.
#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "process/exit_status.h"

namespace pt::grade {

using Clock = std::chrono::steady_clock;

struct SandboxLimits {
  uint64_t address_space = 8ull << 30;  // RLIMIT_AS: the suites need < 100 MiB resident; threads reserve more
  double cpu_seconds = 300;             // RLIMIT_CPU per run, all threads together: a backstop for the wall clock
  uint64_t file_size = 64ull << 20;     // RLIMIT_FSIZE
  uint64_t open_files = 256;            // RLIMIT_NOFILE (hard: it cannot be raised again)
  uint64_t processes = 512;             // RLIMIT_NPROC (threads count), when only the sandbox user's count
  uint64_t workdir_bytes = 256ull << 20;  // size of the private tmpfs working directory
  size_t output_head = 256 << 10, output_tail = 64 << 10;  // bytes of output kept per run
};

struct SandboxOptions {
  bool confine = true;             // false: a plain child process (trusted binaries, debugging)
  std::string user = "nobody";     // who runs the code when the grader is root
  std::vector<std::string> readable;  // paths it may read besides the system's (/usr, /lib, /etc, ...)
  // Layers to leave out even where they work ("namespaces", "user", "landlock",
  // "seccomp"): how the fallbacks are tested on a machine that has them all.
  std::vector<std::string> without;
  SandboxLimits limits;
};

struct RunRequest {
  std::string binary;             // a path; no PATH search
  std::vector<std::string> args;  // argv[1..]
  // When not empty, a verdict channel: this key is written to a pipe on
  // descriptor 4 and whatever the run writes to descriptor 3 goes to
  // RunObserver::on_channel (verdicts.h).
  std::string key;
  // When not empty, an existing folder the run may also write (its private
  // working directory is discarded with it): where a render leaves its images.
  // Handed to the sandbox user when the grader is root, never through a link:
  // its path must hold none (a fresh folder of the grader's: work_area.h).
  std::string output_dir;
  // When not -1, the grader's ends of a link between a verifier and its worker
  // (boundary/README.md): the run reads link_read and writes link_write, as
  // descriptors 5 and 6 beside a verdict channel (a verifier), or as 4 and 3
  // without one (a worker). run() takes them: it closes them once the child
  // has its own, so that each end sees the other's death as the end of file.
  int link_read = -1, link_write = -1;
};

struct Deadline {
  Clock::time_point when;
  double limit_seconds;  // what the report says it was: "timed out after N s"
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void on_channel(std::string_view bytes) = 0;
  virtual Deadline deadline() const = 0;  // asked again after every event
};

struct RunOutcome {
  Exit exit;
  std::string output;         // stdout and stderr interleaved: the head, a gap marker, the tail
  uint64_t output_bytes = 0;  // all it wrote, kept or not

  static RunOutcome not_started(std::string why) {
    RunOutcome r;
    r.exit = Exit::not_started(std::move(why));
    return r;
  }
};

// "" where this build confines code (PT_SANDBOX); otherwise why it cannot,
// for the commands that refuse to grade without it.
std::string sandbox_unavailable();

class Sandbox {
 public:
  explicit Sandbox(SandboxOptions options);
  ~Sandbox();
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  // Runs the binary to its end or its deadline; every process it started is
  // dead when this returns. (This process becomes a child subreaper: without
  // a PID namespace, the run's orphans are handed to it and killed; children
  // it had before the run are left alone.)
  //
  // With a `worker`, `request` is a verifier's and the worker runs beside it,
  // in a run of its own (its own PID namespace where there are namespaces),
  // both started from this thread: the worker's output is read while the
  // verifier runs, and the worker is stopped a second after the verifier has
  // ended. Its outcome is in *worker_run.
  RunOutcome run(const RunRequest& request, RunObserver& observer, const RunRequest* worker = nullptr,
                 RunOutcome* worker_run = nullptr);

  const std::vector<std::string>& layers() const { return active_; }  // e.g. "PID namespace"
  const std::vector<std::string>& layers_missing() const { return missing_; }
  const std::vector<std::string>& layer_ids() const { return ids_; }  // pid-ns, user, landlock, seccomp, no-fork, ...

 private:
  struct Plan;
  void probe();
  // A run's working directory made and handed over, its paths absolute: "" or what failed.
  std::string prepare(const RunRequest& request, RunRequest& absolute, std::string& workdir);

  SandboxOptions options_;
  std::string scratch_;  // the grader's own temporary folder
  Plan* plan_;
  std::vector<std::string> active_, missing_, ids_;
  int runs_ = 0;
};

}  // namespace pt::grade
