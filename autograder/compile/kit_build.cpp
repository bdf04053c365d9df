#include "compile/kit_build.h"

#include <sched.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "compile/work_area.h"
#include "process/command.h"
#include "sandbox/landlock.h"

namespace pt::grade {

namespace {

constexpr unsigned long long kBuildAddressSpace = 4ull << 30;
constexpr size_t kBuildOutputKept = 1 << 20;

std::string shell_quoted(const std::string& word) {
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The system a build needs, and the tree; nothing of the grader's own files
// (its checkout, the kit it copied the tree from, /root, /etc beyond the
// loader's cache).
LandlockRules build_rules(const std::string& tree) {
  LandlockRules r;
  const std::vector<std::string> system = {"/usr", "/lib", "/lib64", "/lib32", "/libx32", "/bin", "/sbin"};
  r.read = system;
  r.read.insert(r.read.end(), {"/etc/ld.so.cache", "/dev/urandom"});
  r.execute = system;
  r.execute.push_back(tree + "/bin");
  r.write = {tree};
  r.devices = {"/dev/null"};
  return r;
}

// An IPC namespace of the build's own, where the kernel allows one: System V
// objects and POSIX message queues made during the build die with it. As
// root it is one unshare(); otherwise it needs a user namespace, which maps
// only the grader's own ids to themselves. Best effort: the build runs no
// code of the submission, so this is depth, not a layer the report names.
void own_ipc_namespace() {
  if (::unshare(CLONE_NEWIPC) == 0) return;
  const uid_t uid = ::geteuid();
  const gid_t gid = ::getegid();
  if (::unshare(CLONE_NEWUSER | CLONE_NEWIPC) != 0) return;
  std::ofstream("/proc/self/setgroups") << "deny";
  std::ofstream("/proc/self/uid_map") << uid << " " << uid << " 1";
  std::ofstream("/proc/self/gid_map") << gid << " " << gid << " 1";
}

}  // namespace

KitBuild::KitBuild(std::string tree, bool confine) : tree_(std::move(tree)) {
  std::error_code ec;
  std::filesystem::create_directories(tree_ + "/tmp", ec);  // TMPDIR: the compiler's temporary files
  const int abi = landlock_abi();
  if (!confine) {
    unconfined_ = "Landlock left out (--no-sandbox or --sandbox-without landlock)";
  } else if (abi == 0) {
    unconfined_ = "this kernel does not offer Landlock";
  } else {
    std::string error;
    ruleset_ = landlock_ruleset(build_rules(tree_), abi, &error);
    if (ruleset_ < 0) unconfined_ = "Landlock: " + error;
  }
}

KitBuild::~KitBuild() {
  if (ruleset_ >= 0) ::close(ruleset_);
}

int KitBuild::run(const std::vector<std::string>& argv, double seconds, std::string* output) const {
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.1f", seconds);
  std::string cmd = "exec timeout --kill-after=5 " + std::string(secs) + " prlimit --as=" +
                    std::to_string(kBuildAddressSpace) + " --fsize=" + std::to_string(kDiskBytes) + " --";
  for (const auto& a : argv) cmd += " " + shell_quoted(a);
  CommandOptions options;
  options.max_output = kBuildOutputKept;
  options.parent_death_signal = SIGTERM;
  options.stop_when = over_;  // `timeout` passes it on to the whole build
  const std::string tmp = tree_ + "/tmp";
  const int ruleset = ruleset_;
  options.in_child = [tmp, ruleset]() -> std::string {
    ::setenv("TMPDIR", tmp.c_str(), 1);
    own_ipc_namespace();
    if (ruleset < 0) return "";
    if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return "pt-grade: cannot confine the build (no_new_privs)";
    const std::string error = landlock_enforce(ruleset);
    return error.empty() ? "" : "pt-grade: cannot confine the build: " + error;
  };
  return run_command({"/bin/sh", "-c", cmd + " 2>&1"}, output, options);
}

}  // namespace pt::grade
