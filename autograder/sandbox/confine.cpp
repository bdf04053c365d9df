#include "sandbox/confine.h"

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "process/launcher.h"
#include "sandbox/landlock.h"
#include "sandbox/seccomp_filter.h"

namespace pt::grade::confine {
namespace {

void say(const ChildArgs& a, const std::string& line) {
  const std::string text = line + "\n";
  [[maybe_unused]] auto n = ::write(a.status, text.data(), text.size());
}

// Reports a failed step, which ends a real run here.
bool step(const ChildArgs& a, const char* name, bool ok, const std::string& what = "") {
  if (ok) return true;
  const int err = errno;
  say(a, std::string("fail ") + name + " " + std::to_string(err) + " " + (what.empty() ? std::strerror(err) : what));
  if (!a.probe) ::_exit(127);
  return false;
}

bool write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  return static_cast<bool>(out << text << std::flush);
}

// The run's user namespace maps only the grader's own ids, to themselves:
// after exec the code under test holds no capability, inside or out.
bool map_ids(const ChildArgs& a) {
  return write_text("/proc/self/setgroups", "deny") &&
         write_text("/proc/self/uid_map", std::to_string(a.outer_uid) + " " + std::to_string(a.outer_uid) + " 1") &&
         write_text("/proc/self/gid_map", std::to_string(a.outer_gid) + " " + std::to_string(a.outer_gid) + " 1");
}

bool set_limit(int resource, rlim_t value) {
  const rlimit r{value, value};
  return ::setrlimit(resource, &r) == 0;
}

bool set_limits(const Plan& p) {
  const SandboxLimits& l = p.limits;
  const auto cpu = static_cast<rlim_t>(l.cpu_seconds + 0.5);
  const rlimit cpu_limit{cpu, cpu + 5};  // SIGXCPU, then SIGKILL
  return set_limit(RLIMIT_AS, l.address_space) && ::setrlimit(RLIMIT_CPU, &cpu_limit) == 0 &&
         set_limit(RLIMIT_FSIZE, l.file_size) && set_limit(RLIMIT_NOFILE, l.open_files) && set_limit(RLIMIT_CORE, 0) &&
         (!p.nproc || set_limit(RLIMIT_NPROC, l.processes));
}

LandlockRules landlock_rules(const ChildArgs& a) {
  LandlockRules r;
  r.read = {"/usr", "/lib", "/lib64", "/lib32", "/libx32", "/bin", "/etc", "/proc", "/sys", "/dev"};
  r.read.insert(r.read.end(), a.plan->readable.begin(), a.plan->readable.end());
  r.write = {a.workdir};
  if (!a.output_dir.empty()) r.write.push_back(a.output_dir);
  r.execute = {a.binary_path};
  if (const std::string loader = elf_interpreter(a.binary_path); !loader.empty()) r.execute.push_back(loader);
  r.devices = {"/dev/null"};
  return r;
}

// Descriptors to their fixed numbers; everything else closed.
bool place_descriptors(const ChildArgs& a) {
  // Out of the way first, so that no dup2 below overwrites a source.
  auto high = [](int fd) { return fd < 0 ? -1 : ::fcntl(fd, F_DUPFD_CLOEXEC, 100); };
  const int null_fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  const int in = high(null_fd), out = high(a.output), verdicts = high(a.verdicts), key = high(a.key);
  const int status = high(a.status), binary = high(a.binary);
  const int link_read = high(a.link_read), link_write = high(a.link_write);
  bool ok = in >= 0 && out >= 0 && status >= 0 && binary >= 0 && (link_read < 0) == (a.link_read < 0) &&
            (link_write < 0) == (a.link_write < 0);
  ok = ok && ::dup2(in, 0) == 0 && ::dup2(out, 1) == 1 && ::dup2(out, 2) == 2;
  ok = ok && (verdicts < 0 ? (::close(3), true) : ::dup2(verdicts, 3) == 3);
  ok = ok && (key < 0 ? (::close(4), true) : ::dup2(key, 4) == 4);
  ok = ok && ::dup3(status, kStatusFd, O_CLOEXEC) == kStatusFd && ::dup3(binary, kBinaryFd, O_CLOEXEC) == kBinaryFd;
  ok = ok && (link_read < 0 || ::dup2(link_read, 5) == 5) && (link_write < 0 || ::dup2(link_write, 6) == 6);
  if (!ok) return false;
  ::close_range(link_read < 0 ? 5 : 7, kStatusFd - 1, 0);
  ::close_range(kBinaryFd + 1, ~0u, 0);
  return true;
}

[[noreturn]] void confine_and_exec(ChildArgs a) {
  const Plan& p = *a.plan;
  const bool placed = place_descriptors(a);
  if (placed) a.status = kStatusFd;
  step(a, "descriptors", placed);
  step(a, "session", ::setsid() >= 0);
  step(a, "workdir", ::chdir(a.workdir.c_str()) == 0, a.workdir);
  int ruleset = -1;
  if (p.landlock_abi > 0) {  // before giving up root: the paths are opened now
    std::string error;
    ruleset = landlock_ruleset(landlock_rules(a), p.landlock_abi, &error);
    step(a, "landlock", ruleset >= 0, error);
  }
  if (p.switch_user)
    step(a, "user", ::setgroups(0, nullptr) == 0 && ::setgid(p.gid) == 0 && ::setuid(p.uid) == 0 && ::getuid() == p.uid);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // after setuid(), which clears it
  step(a, "rlimits", set_limits(p));
  step(a, "no-new-privs", ::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0);
  if (ruleset >= 0) {
    const std::string error = landlock_enforce(ruleset);
    ::close(ruleset);
    step(a, "landlock", error.empty(), error);
  }
  if (p.seccomp) {
    const std::string error = seccomp_confine(kBinaryFd, ::getpid());
    step(a, "seccomp", error.empty(), error);
  }
  if (a.probe) ::_exit(0);
  ::syscall(SYS_execveat, kBinaryFd, "", a.argv.data(), a.envp.data(), AT_EMPTY_PATH);
  step(a, "exec", false, a.binary_path + ": " + std::strerror(errno));
  ::_exit(127);
}

}  // namespace

void warden_main(const ChildArgs& a) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // the grader gone: the whole run goes (all of it, as PID 1)
  const Plan& p = *a.plan;
  if (p.user_ns) step(a, "uid-map", map_ids(a));
  if (p.mount_ns) {
    step(a, "mount-private", ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0);
    if (p.tmpfs) {
      const uid_t owner = p.switch_user ? p.uid : a.outer_uid;
      const gid_t group = p.switch_user ? p.gid : a.outer_gid;
      std::ostringstream opts;
      opts << "size=" << p.limits.workdir_bytes << ",mode=0700,uid=" << owner << ",gid=" << group;
      step(a, "tmpfs", ::mount("pt-grade", a.workdir.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, opts.str().c_str()) == 0);
    }
    if (p.proc) step(a, "proc", ::mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr) == 0);
  }
  if (!p.pid_ns) ::prctl(PR_SET_CHILD_SUBREAPER, 1);
  Child test({}, [&a] { confine_and_exec(a); });
  if (!test.started()) {
    errno = test.start_error();
    step(a, "fork", false);
    ::_exit(127);
  }
  // The warden keeps only its status pipe: the run's other pipes, and those
  // of a run beside it (a verifier's worker), must end when their writers do.
  if (a.status > 0) ::close_range(0, static_cast<unsigned>(a.status) - 1, 0);
  ::close_range(static_cast<unsigned>(a.status) + 1, ~0u, 0);
  const int status = test.wait_reaping_others();
  // What the run left behind: as PID 1 of its namespace, every other process
  // in it; as a subreaper, every orphan it has inherited.
  if (p.pid_ns)
    kill_namespace();
  else
    kill_descendants({});
  say(a, "exit " + std::to_string(status));
  ::_exit(0);
}

}  // namespace pt::grade::confine
