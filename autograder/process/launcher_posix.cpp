// The launcher's start where Linux's process interfaces are not (a build
// without the sandbox, PT_SANDBOX off: macOS): fork() only, no namespaces and
// no parent death signal, and no process tree from /proc (children_of,
// kill_namespace and kill_descendants are the sandbox's, not built here).
// A child that outlives its parent is stopped by kill_group() instead:
// sandbox/unconfined.cpp starts each run in its own process group.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "process/launcher.h"

namespace pt::grade {

bool Pipe::open() {
  // No pipe2() here: this build starts children from one thread, so nothing
  // can fork between pipe() and the flags.
  int fds[2];
  if (::pipe(fds) != 0) return false;
  read = Fd(fds[0]);
  write = Fd(fds[1]);
  return ::fcntl(fds[0], F_SETFD, FD_CLOEXEC) == 0 && ::fcntl(fds[1], F_SETFD, FD_CLOEXEC) == 0;
}

Child::Child(const LaunchOptions& options, const std::function<void()>& body) {
  if (options.namespaces != 0) {  // only the sandbox asks for them
    error_ = ENOSYS;
    for (int fd : options.child_ends)
      if (fd >= 0) ::close(fd);
    return;
  }
  std::fflush(nullptr);  // what this process buffered must not come out twice
  pid_ = ::fork();
  if (pid_ == 0) {
    body();
    ::_exit(127);
  }
  if (pid_ < 0) error_ = errno;
  for (int fd : options.child_ends)
    if (fd >= 0) ::close(fd);
}

}  // namespace pt::grade
