#include "process/launcher.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>

namespace pt::grade {

Fd& Fd::operator=(Fd&& other) noexcept {
  if (this != &other) {
    reset();
    fd_ = other.release();
  }
  return *this;
}

int Fd::release() {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

void Fd::reset() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

Child::~Child() {
  if (!started() || reaped_) return;
  kill(SIGKILL);
  wait();
}

bool Child::exited() {
  if (reaped_) return true;
  const pid_t r = ::waitpid(pid_, &status_, WNOHANG);
  reaped_ = r == pid_ || (r < 0 && errno == ECHILD);
  return reaped_;
}

namespace {

// One read from a descriptor poll() found ready; false at its end.
bool read_some(const Stream& s) {
  char buf[65536];
  const ssize_t n = ::read(s.fd, buf, sizeof buf);
  if (n > 0) {
    if (s.sink) s.sink(buf, static_cast<size_t>(n));
    return true;
  }
  return n < 0 && (errno == EINTR || errno == EAGAIN);
}

}  // namespace

bool Child::watch(std::vector<Stream>& streams, int until, const std::function<Clock::time_point()>& deadline,
                  const std::function<void()>& tick) {
  std::vector<pollfd> fds(streams.size());
  for (size_t i = 0; i < streams.size(); ++i) fds[i] = {streams[i].fd, POLLIN, 0};
  const auto period = std::chrono::milliseconds(250);
  auto next_tick = Clock::now();
  for (;;) {
    if (until >= 0 ? fds[static_cast<size_t>(until)].fd < 0 : exited()) return true;
    const auto now = Clock::now();
    const auto end = deadline ? deadline() : Clock::time_point::max();
    if (now >= end) return false;
    if (tick && now >= next_tick) {
      tick();
      next_tick = now + period;
    }
    // Without a stream to end the watch, the child's exit is looked for
    // every 10 ms; otherwise a stream's end wakes the poll.
    auto wait = std::min<Clock::duration>(end - now, until >= 0 ? std::chrono::milliseconds(200)
                                                                : std::chrono::milliseconds(10));
    if (tick) wait = std::min<Clock::duration>(wait, next_tick - now);
    const int ms = static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(wait).count()) + 1;
    if (::poll(fds.data(), fds.size(), ms) < 0 && errno != EINTR) return true;
    for (size_t i = 0; i < streams.size(); ++i)
      if (fds[i].fd >= 0 && fds[i].revents != 0 && !read_some(streams[i])) fds[i].fd = -1;
  }
}

void Child::kill(int signal) const {
  if (started()) ::kill(pid_, signal);
}

void Child::kill_group(int signal) const {
  if (started()) ::kill(-pid_, signal);
}

int Child::wait() {
  while (started() && !reaped_) {
    const pid_t r = ::waitpid(pid_, &status_, 0);
    reaped_ = r == pid_ || (r < 0 && errno != EINTR);
  }
  return status_;
}

int Child::wait_reaping_others() {
  while (started() && !reaped_) {
    int status = 0;
    const pid_t r = ::waitpid(-1, &status, 0);
    if (r == pid_) status_ = status;
    reaped_ = r == pid_ || (r < 0 && errno != EINTR);
  }
  return status_;
}

void drain(const Stream& stream) {
  if (stream.fd < 0) return;
  ::fcntl(stream.fd, F_SETFL, O_NONBLOCK);
  for (;;) {
    char buf[65536];
    const ssize_t n = ::read(stream.fd, buf, sizeof buf);
    if (n > 0 && stream.sink) stream.sink(buf, static_cast<size_t>(n));
    if (n == 0 || (n < 0 && errno != EINTR)) return;
  }
}

int shell_status(int wait_status) {
  return WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : 128 + WTERMSIG(wait_status);
}

}  // namespace pt::grade
