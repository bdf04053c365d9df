#pragma once
// Starting a process and seeing it end: the one place the grader and a
// verifier start one (command.h, sandbox/sandbox.cpp and sandbox/confine.cpp,
// sandbox/unconfined.cpp, boundary/verifier_link.cpp). This is
// the parent's side only; what a child does between its start and exec (the
// sandbox's namespaces, limits, Landlock, seccomp: sandbox/confine.h) is the
// body it is given.
//
//   start     fork(), or clone() with namespace flags (then the child is PID 1
//             of its own PID namespace); a child can be sent a signal when
//             the thread that started it ends, set before its body runs
//   pipes     close-on-exec, so that a child keeps only what it places; the
//             child's ends closed here once it has them, so that each end sees
//             the other's death as the end of file; this end read into sinks
//   deadline  asked again after every read; past it the watch returns, and
//             the caller stops the child (SIGKILL, or SIGTERM to its group)
//   tree      a child is reaped once, and killed first if it still runs when
//             its handle goes; what it leaves behind dies with its PID
//             namespace (kill_namespace) or is killed by a child subreaper
//             (kill_descendants)
//
// Async-signal-safe in the child up to the body: a multi-threaded process
// (a verifier) may start a child whose body only places descriptors and execs.
#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <set>
#include <vector>

namespace pt::grade {

// A descriptor, closed with its owner.
class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) : fd_(fd) {}
  Fd(Fd&& other) noexcept : fd_(other.release()) {}
  Fd& operator=(Fd&& other) noexcept;
  ~Fd() { reset(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;

  int get() const { return fd_; }
  int release();  // no longer closed here
  void reset();   // closed now

 private:
  int fd_ = -1;
};

// A pipe with both ends close-on-exec.
struct Pipe {
  Fd read, write;
  bool open();  // false (errno set) when the system has no pipe to give
};

struct LaunchOptions {
  unsigned long namespaces = 0;  // CLONE_NEW* flags: clone() instead of fork()
  int parent_death_signal = 0;   // sent to the child when the thread that started it ends
  std::vector<int> child_ends;   // descriptors only the child uses: closed here once it has them
};

// One descriptor the parent reads from its child until the end of file.
struct Stream {
  int fd = -1;  // -1: none (already at its end)
  std::function<void(const char*, size_t)> sink;  // none: read and dropped
};

class Child {
 public:
  using Clock = std::chrono::steady_clock;

  // Starts `body` in a new process. The body must not return (exec or
  // _exit); if it does, the child exits with status 127.
  Child(const LaunchOptions& options, const std::function<void()>& body);
  ~Child();  // a child still running is killed (SIGKILL) and reaped
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  bool started() const { return pid_ > 0; }
  int start_error() const { return error_; }  // errno of fork() or clone()
  pid_t pid() const { return pid_; }

  // Reads `streams` into their sinks until the one at index `until` ends
  // (with until < 0: until the child has exited), or until `deadline()`
  // passes: false then. `tick`, when given, is called four times a second
  // whether or not anything arrives.
  bool watch(std::vector<Stream>& streams, int until, const std::function<Clock::time_point()>& deadline,
             const std::function<void()>& tick = {});

  void kill(int signal) const;        // the child alone
  void kill_group(int signal) const;  // its process group: a child that leads one
  // Its wait status once it has ended (a later call gives the same).
  int wait();
  // The same for a process that other processes are handed to (PID 1 of a
  // namespace, a child subreaper): each of them is reaped as it ends.
  int wait_reaping_others();

 private:
  bool exited();  // reaped now if it has ended

  pid_t pid_ = -1;
  int error_ = 0;
  bool reaped_ = false;
  int status_ = 0;
};

// What is left in a stream once every process that could write it is dead.
void drain(const Stream& stream);

// A wait status as a shell says it: the exit code, or 128 + the signal.
int shell_status(int wait_status);

// The children of a process (all its threads'), from /proc.
std::set<pid_t> children_of(pid_t pid);

// As PID 1 of a PID namespace: every other process in it killed and reaped.
void kill_namespace();

// As a child subreaper outside the run's PID namespace: every descendant but
// the `spare` children and theirs stopped (so that none can fork), killed,
// and reaped as it is handed here.
void kill_descendants(const std::set<pid_t>& spare);

}  // namespace pt::grade
