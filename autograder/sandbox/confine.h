#pragma once
// What the sandbox's child processes do between clone() and exec, used only
// by sandbox.cpp. The warden is PID 1 of the run's PID namespace (or, without
// one, a child subreaper): it sets up the namespaces, forks the process that
// becomes the code under test, waits for it, kills whatever it left behind and
// reports its exit status. The other process confines itself layer by layer
// and executes the test binary.
//
// Both report on the status pipe, one line per failed step and one at the end:
//   fail STEP ERRNO WHAT | exit WAIT_STATUS
// In a probe (Sandbox's first run) a step that fails is reported and skipped;
// in a real run it ends the run before any code under test starts.
#include <sys/types.h>

#include <string>
#include <vector>

#include "sandbox/sandbox.h"

namespace pt::grade::confine {

struct Plan {
  bool user_ns = false, pid_ns = false, mount_ns = false, ipc_ns = false;  // clone() flags
  bool tmpfs = false, proc = false;                        // mounts in the mount namespace
  bool switch_user = false;
  uid_t uid = 0;
  gid_t gid = 0;
  bool nproc = false;  // RLIMIT_NPROC counts only this run's processes (a user of its own or namespace)
  int landlock_abi = 0;  // 0: no Landlock
  bool seccomp = false;
  SandboxLimits limits;
  std::vector<std::string> readable;
};

// Fixed descriptor numbers in the code under test. The binary's descriptor
// sits above the open-files limit, where the code under test can never
// create one, which is what lets seccomp allow exactly that exec.
inline constexpr int kStatusFd = 1022, kBinaryFd = 1023;

struct ChildArgs {
  const Plan* plan = nullptr;
  bool probe = false;  // set everything up and report, but do not exec
  int status = -1, output = -1, verdicts = -1, key = -1, binary = -1;  // inherited descriptors (-1: none)
  int link_read = -1, link_write = -1;  // a verifier's link to its worker: placed at 5 and 6
  std::string binary_path, workdir;
  std::string output_dir;  // also writable, when not empty (RunRequest::output_dir)
  std::vector<char*> argv, envp;  // null-terminated
  uid_t outer_uid = 0;
  gid_t outer_gid = 0;
};

[[noreturn]] void warden_main(const ChildArgs& args);

}  // namespace pt::grade::confine
