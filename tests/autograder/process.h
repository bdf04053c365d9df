#pragma once
// Running a test binary so that whatever it does (crash, hang, fork helpers,
// flood its output) cannot take the grader down with it. Linux only.
#include <string>
#include <vector>

namespace pt::grade {

struct Exit {
  enum class How { Exited, Signaled, TimedOut, NotStarted };
  How how = How::NotStarted;
  int code = 0;        // exit status, or the signal number
  double seconds = 0;  // wall-clock
  double limit = 0;    // the timeout it ran under
  std::string error;   // why it did not start

  bool exited_ok() const { return how == How::Exited && code == 0; }
  bool died() const { return how == How::Signaled || how == How::TimedOut; }
  // "exited with status 3", "crashed: signal 11 (SIGSEGV)", "timed out after 60 s", ...
  std::string describe() const;
};

// Runs argv[0] (a path, no PATH search) with stdin from /dev/null and stdout
// and stderr appended to the given files (which may be the same), in a process
// group of its own that is killed whole when it times out or ends.
Exit run_process(const std::vector<std::string>& argv, const std::string& out_path, const std::string& err_path,
                 double timeout_seconds);

}  // namespace pt::grade
