#include "process/command.h"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

namespace pt::grade {

namespace {

int exit_code(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

int run(const std::vector<std::string>& argv, std::string* output, double kill_after, const CommandOptions& options) {
  if (argv.empty()) return -1;
  int fds[2];
  if (::pipe(fds) != 0) return -1;
  std::fflush(nullptr);  // what this process buffered must not come out twice
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    ::dup2(output ? fds[1] : 2, 1);
    ::close(fds[0]);
    ::close(fds[1]);
    if (options.parent_death_signal != 0) {
      ::prctl(PR_SET_PDEATHSIG, options.parent_death_signal);
      if (::getppid() != parent) ::_exit(128 + options.parent_death_signal);  // it died before the line above
    }
    if (options.in_child) {
      const std::string error = options.in_child();
      if (!error.empty()) {
        std::fprintf(stderr, "%s\n", error.c_str());
        ::_exit(126);
      }
    }
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execvp(args[0], args.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  int status = 0;
  if (kill_after > 0 && !output) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(kill_after);
    while (::waitpid(pid, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() >= end) ::kill(pid, SIGKILL);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::close(fds[0]);
    return exit_code(status);
  }
  char buf[65536];
  auto next_check = std::chrono::steady_clock::now();
  for (ssize_t n;;) {
    if (options.stop_when) {  // asked on its own clock, so a program that prints without end is asked too
      pollfd p{fds[0], POLLIN, 0};
      const bool idle = ::poll(&p, 1, 250) == 0;
      if (std::chrono::steady_clock::now() >= next_check) {
        next_check = std::chrono::steady_clock::now() + std::chrono::milliseconds(250);
        // SIGTERM, as when the grader dies: `timeout` (the leader of this
        // group) passes it on, and ninja ends the commands it started in
        // process groups of their own, which a SIGKILL here would miss.
        if (options.stop_when()) ::kill(-pid, SIGTERM);
      }
      if (idle) continue;
    }
    if ((n = ::read(fds[0], buf, sizeof buf)) == 0) break;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    if (output && output->size() < options.max_output)
      output->append(buf, std::min(static_cast<size_t>(n), options.max_output - output->size()));
  }
  ::close(fds[0]);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return exit_code(status);
}

}  // namespace

int run_command(const std::vector<std::string>& argv, std::string* output, double kill_after) {
  return run(argv, output, kill_after, CommandOptions{});
}

int run_command(const std::vector<std::string>& argv, std::string* output, const CommandOptions& options) {
  return run(argv, output, 0, options);
}

void hide_command_line(int argc, char** argv, const char* name) {
  if (argc < 1) return;
  char* begin = argv[0];
  char* end = argv[argc - 1] + std::strlen(argv[argc - 1]);
  std::memset(begin, 0, static_cast<size_t>(end - begin));
  std::strncpy(begin, name, static_cast<size_t>(end - begin));
}

}  // namespace pt::grade
