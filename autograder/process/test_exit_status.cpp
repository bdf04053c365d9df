// How a run ended, in the words a report gives it (exit_status.h).
#include <gtest/gtest.h>

#include <csignal>

#include "process/exit_status.h"

namespace pt::grade {
namespace {

Exit signaled(int sig) {
  Exit e;
  e.how = Exit::How::Signaled;
  e.code = sig;
  return e;
}

TEST(ExitStatus, ASignalIsNamedAsKillNamesIt) {
  // The names come from the grader's own table (portable), not the C library.
  EXPECT_EQ(signaled(SIGSEGV).describe(), "crashed: signal " + std::to_string(SIGSEGV) +
                                              " (SIGSEGV): invalid memory access or stack overflow");
  EXPECT_EQ(signaled(SIGKILL).describe(), "crashed: signal " + std::to_string(SIGKILL) + " (SIGKILL)");
  EXPECT_EQ(signaled(SIGSYS).describe().rfind("crashed: signal " + std::to_string(SIGSYS) + " (SIGSYS): ", 0), 0u);
  EXPECT_EQ(signaled(SIGUSR2).describe(), "crashed: signal " + std::to_string(SIGUSR2) + " (SIGUSR2)");
}

TEST(ExitStatus, ASignalWithoutANameIsGivenByNumber) {
  EXPECT_EQ(signaled(SIGRTMIN + 1).describe(), "crashed: signal " + std::to_string(SIGRTMIN + 1));
}

TEST(ExitStatus, TheOtherEndsSayWhatHappened) {
  Exit e;
  e.how = Exit::How::Exited;
  e.code = 3;
  EXPECT_EQ(e.describe(), "exited with status 3");
  e.how = Exit::How::TimedOut;
  e.limit = 20;
  EXPECT_EQ(e.describe(), "timed out after 20 s");
  e.how = Exit::How::NotStarted;
  e.error = "fork: EAGAIN";
  EXPECT_EQ(e.describe(), "could not start: fork: EAGAIN");
}

}  // namespace
}  // namespace pt::grade
