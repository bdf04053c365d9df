#include "process/exit_status.h"

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

}  // namespace

std::string Exit::describe() const {
  char text[64];
  switch (how) {
    case How::Exited:
      return "exited with status " + std::to_string(code);
    case How::Signaled: {
      const char* abbrev = sigabbrev_np(code);
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
