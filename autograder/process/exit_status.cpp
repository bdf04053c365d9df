#include "process/exit_status.h"

#include <sys/wait.h>

#include <csignal>
#include <cstdio>
#include <cstring>

namespace pt::grade {
namespace {

// What each signal means here, where the sandbox (sandbox.h) is what sends it.
const char* why(int sig) {
  switch (sig) {
    case SIGSYS:
      return ": a system call the sandbox forbids (fork, exec, ptrace, sockets, signals to other processes)";
    case SIGXCPU:
      return ": CPU time limit";
    case SIGXFSZ:
      return ": file size limit";
    case SIGSEGV:
      return ": invalid memory access or stack overflow";
    case SIGABRT:
      return ": abort(), a failed assert() or an uncaught exception";
    default:
      return "";
  }
}

// The signal's name as `kill -l` gives it. No C library call gives it on
// every platform (glibc's sigabbrev_np is its own), and these are POSIX's.
const char* abbreviation(int sig) {
  switch (sig) {
    case SIGHUP: return "HUP";
    case SIGINT: return "INT";
    case SIGQUIT: return "QUIT";
    case SIGILL: return "ILL";
    case SIGTRAP: return "TRAP";
    case SIGABRT: return "ABRT";
    case SIGBUS: return "BUS";
    case SIGFPE: return "FPE";
    case SIGKILL: return "KILL";
    case SIGUSR1: return "USR1";
    case SIGSEGV: return "SEGV";
    case SIGUSR2: return "USR2";
    case SIGPIPE: return "PIPE";
    case SIGALRM: return "ALRM";
    case SIGTERM: return "TERM";
    case SIGCHLD: return "CHLD";
    case SIGCONT: return "CONT";
    case SIGSTOP: return "STOP";
    case SIGTSTP: return "TSTP";
    case SIGTTIN: return "TTIN";
    case SIGTTOU: return "TTOU";
    case SIGURG: return "URG";
    case SIGXCPU: return "XCPU";
    case SIGXFSZ: return "XFSZ";
    case SIGVTALRM: return "VTALRM";
    case SIGPROF: return "PROF";
    case SIGWINCH: return "WINCH";
    case SIGSYS: return "SYS";
    default: return nullptr;
  }
}

}  // namespace

Exit Exit::of_wait_status(int wait_status) {
  Exit e;
  e.how = WIFSIGNALED(wait_status) ? How::Signaled : How::Exited;
  e.code = WIFSIGNALED(wait_status) ? WTERMSIG(wait_status) : WEXITSTATUS(wait_status);
  return e;
}

std::string Exit::describe() const {
  char text[64];
  switch (how) {
    case How::Exited:
      return "exited with status " + std::to_string(code);
    case How::Signaled: {
      const char* abbrev = abbreviation(code);
      return "crashed: signal " + std::to_string(code) + (abbrev ? " (SIG" + std::string(abbrev) + ")" : "") + why(code);
    }
    case How::TimedOut:
      std::snprintf(text, sizeof text, "timed out after %g s", limit);
      return text;
    case How::Lost:
      return "lost: " + error;
    case How::NotStarted:
      break;
  }
  return "could not start: " + error;
}

}  // namespace pt::grade
