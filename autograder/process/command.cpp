#include "process/command.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "process/launcher.h"

namespace pt::grade {

int run_command(const std::vector<std::string>& argv, std::string* output, const CommandOptions& options) {
  if (argv.empty()) return -1;
  Pipe out;
  if (!out.open()) return -1;
  // Built before the start: the child only places descriptors and execs.
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int out_fd = output ? out.write.get() : 2;
  const std::function<std::string()>& in_child = options.in_child;
  LaunchOptions launch;
  launch.parent_death_signal = options.parent_death_signal;
  launch.child_ends = {out.write.release()};
  Child child(launch, [&] {
    ::dup2(out_fd, 1);
    if (in_child) {
      const std::string error = in_child();
      if (!error.empty()) {
        std::fprintf(stderr, "%s\n", error.c_str());
        ::_exit(126);
      }
    }
    ::execvp(args[0], args.data());
    ::_exit(127);
  });
  if (!child.started()) return -1;
  const auto start = Child::Clock::now();
  std::vector<Stream> streams{{out.read.get(), [&](const char* data, size_t n) {
                                 if (output && output->size() < options.max_output)
                                   output->append(data, std::min(n, options.max_output - output->size()));
                               }}};
  if (options.kill_after > 0) {
    const auto end =
        start + std::chrono::duration_cast<Child::Clock::duration>(std::chrono::duration<double>(options.kill_after));
    if (!child.watch(streams, -1, [end] { return end; })) child.kill(SIGKILL);
    return shell_status(child.wait());
  }
  // SIGTERM, as when the grader dies: `timeout` (the leader of this group)
  // passes it on, and ninja ends the commands it started in process groups
  // of their own, which a SIGKILL here would miss. Asked on its own clock, so
  // that a program that prints without end is asked too.
  std::function<void()> tick;
  if (options.stop_when)
    tick = [&] {
      if (options.stop_when()) child.kill_group(SIGTERM);
    };
  child.watch(streams, 0, {}, tick);
  return shell_status(child.wait());
}

void hide_command_line(int argc, char** argv, const char* name) {
  if (argc < 1) return;
  char* begin = argv[0];
  char* end = argv[argc - 1] + std::strlen(argv[argc - 1]);
  std::memset(begin, 0, static_cast<size_t>(end - begin));
  std::strncpy(begin, name, static_cast<size_t>(end - begin));
}

}  // namespace pt::grade
