// The launcher's contract (launcher.h), clause by clause: a child's pipes end
// when it does, a deadline stops the watch, a handle that goes kills its
// child, a subreaper kills a whole tree, and what a start that fails says.
#include <gtest/gtest.h>

#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "process/launcher.h"

namespace pt::grade {
namespace {

using namespace std::chrono_literals;

bool alive(pid_t pid) { return ::kill(pid, 0) == 0; }

// Runs `/bin/sh -c script` with its standard output on a pipe.
struct Shell {
  Pipe out;
  std::unique_ptr<Child> child;
  explicit Shell(const char* script, LaunchOptions launch = {}) {
    EXPECT_TRUE(out.open());
    const int write_end = out.write.get();
    launch.child_ends.push_back(out.write.release());
    child = std::make_unique<Child>(launch, [write_end, script] {
      ::dup2(write_end, 1);
      ::execl("/bin/sh", "sh", "-c", script, static_cast<char*>(nullptr));
    });
  }
};

TEST(Launcher, ReadsTheChildsOutputToItsEndAndItsExitStatus) {
  Shell sh("printf one; printf two; exit 3");
  ASSERT_TRUE(sh.child->started());
  std::string text;
  std::vector<Stream> streams{{sh.out.read.get(), [&](const char* d, size_t n) { text.append(d, n); }}};
  const auto end = Child::Clock::now() + 20s;
  EXPECT_TRUE(sh.child->watch(streams, 0, [end] { return end; }));
  EXPECT_EQ(text, "onetwo");
  EXPECT_EQ(shell_status(sh.child->wait()), 3);
}

// The parent's copy of the child's end is closed once the child has it:
// otherwise the stream would never end, and the watch would reach its deadline.
TEST(Launcher, TheChildsEndsAreClosedHereSoItsStreamEnds) {
  Shell sh("exit 0");
  std::vector<Stream> streams{{sh.out.read.get(), {}}};
  const auto end = Child::Clock::now() + 20s;
  EXPECT_TRUE(sh.child->watch(streams, 0, [end] { return end; }));
}

TEST(Launcher, ADeadlineEndsTheWatchAndTheCallerStopsTheChild) {
  Shell sh("exec sleep 30");
  std::vector<Stream> streams{{sh.out.read.get(), {}}};
  const auto start = Child::Clock::now();
  EXPECT_FALSE(sh.child->watch(streams, 0, [start] { return start + 200ms; }));
  EXPECT_LT(Child::Clock::now() - start, 10s);
  sh.child->kill(SIGKILL);
  const int status = sh.child->wait();
  EXPECT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

TEST(Launcher, WatchingForTheExitItselfEndsWhenTheChildExits) {
  Shell sh("exit 5");
  std::vector<Stream> none;
  const auto end = Child::Clock::now() + 20s;
  EXPECT_TRUE(sh.child->watch(none, -1, [end] { return end; }));
  EXPECT_EQ(shell_status(sh.child->wait()), 5);
}

TEST(Launcher, TheTickIsAskedWhileTheChildIsSilent) {
  Shell sh("exec sleep 30");
  std::vector<Stream> streams{{sh.out.read.get(), {}}};
  int ticks = 0;
  // Stopping from the tick, as a bound no limit enforces does (command.h's stop_when).
  EXPECT_TRUE(sh.child->watch(streams, 0, {}, [&] {
    if (++ticks == 3) sh.child->kill(SIGTERM);
  }));
  EXPECT_GE(ticks, 3);
  EXPECT_EQ(WTERMSIG(sh.child->wait()), SIGTERM);
}

TEST(Launcher, AHandleThatGoesKillsItsChild) {
  pid_t pid = 0;
  {
    Shell sh("exec sleep 30");
    pid = sh.child->pid();
    ASSERT_TRUE(alive(pid));
  }
  EXPECT_FALSE(alive(pid));  // killed and reaped: not even a zombie is left
}

TEST(Launcher, TheExitStatusIsKeptForALaterWait) {
  Shell sh("exit 7");
  EXPECT_EQ(shell_status(sh.child->wait()), 7);
  EXPECT_EQ(shell_status(sh.child->wait()), 7);
}

TEST(Launcher, ASignalEndsAsAShellSaysIt) {
  Shell sh("kill -9 $$");
  EXPECT_EQ(shell_status(sh.child->wait()), 128 + SIGKILL);
}

// A child subreaper kills what its child left behind: here a grandchild that
// outlives its parent, reparented to this process.
TEST(Launcher, ASubreaperKillsEveryDescendantButThoseSpared) {
  Shell spared("exec sleep 30");
  int was_subreaper = 0;
  ::prctl(PR_GET_CHILD_SUBREAPER, &was_subreaper);
  ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0);
  Shell leaver("sleep 30 & echo $!");
  std::string text;
  std::vector<Stream> streams{{leaver.out.read.get(), [&](const char* d, size_t n) { text.append(d, n); }}};
  const auto end = Child::Clock::now() + 20s;
  leaver.child->watch(streams, -1, [end] { return end; });  // sh exits at once; its sleep runs on
  drain(streams[0]);  // what sh printed before it exited (its sleep holds the pipe open)
  const pid_t grandchild = static_cast<pid_t>(std::stol(text));
  ASSERT_TRUE(alive(grandchild));
  kill_descendants({spared.child->pid()});
  ::prctl(PR_SET_CHILD_SUBREAPER, was_subreaper);
  EXPECT_FALSE(alive(grandchild));
  EXPECT_TRUE(alive(spared.child->pid()));
}

// The signal follows the thread that started the child (a verifier starts
// its worker from a thread that lives as long as it does).
TEST(Launcher, TheParentDeathSignalReachesAChildWhenItsStarterEnds) {
  std::unique_ptr<Child> child;
  std::thread([&] {
    LaunchOptions launch;
    launch.parent_death_signal = SIGKILL;
    child = std::make_unique<Child>(launch, [] { ::execl("/bin/sleep", "sleep", "30", static_cast<char*>(nullptr)); });
  }).join();
  ASSERT_TRUE(child->started());
  const int status = child->wait();  // 30 s and an exit status without the signal
  EXPECT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

TEST(Launcher, AStartThatFailsSaysWhy) {
  LaunchOptions launch;
  launch.namespaces = CLONE_NEWNS | CLONE_FS;  // clone(2): EINVAL, always
  Child child(launch, [] { ::_exit(0); });
  EXPECT_FALSE(child.started());
  EXPECT_NE(child.start_error(), 0);
}

}  // namespace
}  // namespace pt::grade
