#include "process.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace pt::grade {
namespace {

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

int open_append(const std::string& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
}

// The death signal set in the child reaches only the child itself: when the
// grader is interrupted or terminated, the whole group of the running test
// must go too, helpers included.
volatile sig_atomic_t running_group = 0;

void kill_group_and_die(int sig) {
  if (running_group > 0) ::kill(-running_group, SIGKILL);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_interrupt_handlers() {
  static const bool installed = [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
      if (::signal(sig, kill_group_and_die) == SIG_IGN) ::signal(sig, SIG_IGN);  // e.g. under nohup
    return true;
  }();
  (void)installed;
}

Exit not_started(std::string why) {
  Exit e;
  e.error = std::move(why);
  return e;
}

}  // namespace

std::string Exit::describe() const {
  char limit_text[32];
  std::snprintf(limit_text, sizeof limit_text, "%g", limit);
  switch (how) {
    case How::Exited:
      return "exited with status " + std::to_string(code);
    case How::Signaled: {
      const char* abbrev = sigabbrev_np(code);
      return "crashed: signal " + std::to_string(code) + (abbrev ? " (SIG" + std::string(abbrev) + ")" : "");
    }
    case How::TimedOut:
      return "timed out after " + std::string(limit_text) + " s";
    case How::NotStarted:
      break;
  }
  return "could not start: " + error;
}

Exit run_process(const std::vector<std::string>& argv, const std::string& out_path, const std::string& err_path,
                 double timeout_seconds) {
  using Clock = std::chrono::steady_clock;
  if (argv.empty()) return not_started("no command");
  Fd in{::open("/dev/null", O_RDONLY | O_CLOEXEC)};
  Fd out{open_append(out_path)};
  Fd err{err_path == out_path ? -1 : open_append(err_path)};
  if (in.fd < 0 || out.fd < 0 || (err_path != out_path && err.fd < 0))
    return not_started("cannot open its output files: " + std::string(std::strerror(errno)));
  const int err_fd = err.fd >= 0 ? err.fd : out.fd;

  // A close-on-exec pipe tells exec failure (errno arrives) from success (EOF).
  int exec_pipe[2];
  if (::pipe2(exec_pipe, O_CLOEXEC) != 0) return not_started(std::strerror(errno));
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  install_interrupt_handlers();
  const pid_t grader = ::getpid();
  const auto start = Clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(exec_pipe[0]);
    ::close(exec_pipe[1]);
    return not_started(std::strerror(errno));
  }
  if (pid == 0) {
    // Own group: a timeout kills the test and anything it spawned. The death
    // signal stops an orphaned test from running on if the grader is killed.
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != grader) ::_exit(127);
    ::dup2(in.fd, 0);
    ::dup2(out.fd, 1);
    ::dup2(err_fd, 2);
    ::execv(args[0], args.data());
    const int e = errno;
    [[maybe_unused]] auto n = ::write(exec_pipe[1], &e, sizeof e);
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also here, so that the group exists before any kill below
  running_group = pid;
  ::close(exec_pipe[1]);
  int exec_errno = 0;
  ssize_t got;
  while ((got = ::read(exec_pipe[0], &exec_errno, sizeof exec_errno)) < 0 && errno == EINTR) {
  }
  ::close(exec_pipe[0]);

  Exit result;
  result.limit = timeout_seconds;
  const auto deadline =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_seconds));
  auto nap = std::chrono::milliseconds(1);
  while (got <= 0) {
    // WNOWAIT leaves the child a zombie, so its pid (the group id) cannot be
    // reused before the group is killed below.
    siginfo_t info{};
    if (::waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) != 0 && errno != EINTR) break;
    if (info.si_pid == pid) break;
    if (Clock::now() >= deadline) {
      result.how = Exit::How::TimedOut;
      break;
    }
    std::this_thread::sleep_for(nap);
    nap = std::min(nap * 2, std::chrono::milliseconds(50));
  }
  ::kill(-pid, SIGKILL);  // a timeout, or helpers the test left behind
  running_group = 0;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();

  if (got > 0) return not_started(std::strerror(exec_errno));
  if (result.how == Exit::How::TimedOut) return result;
  if (WIFSIGNALED(status)) {
    result.how = Exit::How::Signaled;
    result.code = WTERMSIG(status);
  } else {
    result.how = Exit::How::Exited;
    result.code = WEXITSTATUS(status);
  }
  return result;
}

}  // namespace pt::grade
