#pragma once
// How a run of code under test ended, in words a student can act on.
#include <string>
#include <utility>

namespace pt::grade {

struct Exit {
  enum class How { Exited, Signaled, TimedOut, NotStarted, Lost };
  How how = How::NotStarted;
  int code = 0;        // exit status, or the signal number
  double seconds = 0;  // wall-clock
  double limit = 0;    // the time limit it ran under (TimedOut)
  std::string error;   // why it did not start (NotStarted), or how it was lost (Lost)

  // A run that never started, and why.
  static Exit not_started(std::string why) {
    Exit e;
    e.error = std::move(why);
    return e;
  }
  static Exit timed_out(double limit_seconds) {
    Exit e;
    e.how = How::TimedOut;
    e.limit = limit_seconds;
    return e;
  }
  static Exit of_wait_status(int wait_status);  // exited or signaled, as waitpid() said

  bool exited_ok() const { return how == How::Exited && code == 0; }
  bool died() const { return how == How::Signaled || how == How::TimedOut || how == How::Lost; }
  // "exited with status 3", "crashed: signal 11 (SIGSEGV)", "timed out after 20 s", ...
  // Signals the sandbox's own limits raise say which limit it was.
  std::string describe() const;
};

}  // namespace pt::grade
