#pragma once
// Running a trusted helper program (nm, readelf, pt-grade, the compiler) and
// keeping its standard output. Not for code under test: that goes through
// sandbox.h.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace pt::grade {

struct CommandOptions {
  // Bytes of output kept; the rest is read and dropped, so that a program
  // that prints without end costs no memory.
  size_t max_output = std::string::npos;
  // The signal the program gets when this process dies (0: none), so that a
  // grader killed from outside leaves nothing running.
  int parent_death_signal = 0;
  // Runs in the child between fork and exec (confinement); a non-empty
  // return is what failed, and the child exits with status 126.
  std::function<std::string()> in_child;
  // Asked about every quarter second while the program runs; true sends its
  // process group SIGTERM: how a bound that no limit enforces is kept.
  std::function<bool()> stop_when;
  // > 0: the program is killed with SIGKILL after that many seconds.
  double kill_after = 0;
};

// Runs argv[0] (a path, or a name looked up in PATH) and appends its standard
// output to *output when given (else it goes to standard error); standard
// error passes through. Returns its exit status, 128 + the signal when a
// signal ended it, or -1 when it could not start.
int run_command(const std::vector<std::string>& argv, std::string* output, const CommandOptions& options = {});

// Blanks this process's command line where the kernel reads it for
// /proc/PID/cmdline, leaving `name`: the grader's names the results, the
// report and the kit, and code under test can read /proc (the grader's own
// entry without a PID namespace; the sandbox's first process, a copy of the
// grader, with one). Call it once the arguments are parsed into copies.
void hide_command_line(int argc, char** argv, const char* name);

}  // namespace pt::grade
