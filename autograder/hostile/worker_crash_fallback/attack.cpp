// Hostile (or just broken), on a machine without the sandbox's namespaces,
// Landlock and seccomp: a SIGSEGV in one task of a part graded across the
// process boundary, and a forked child left running. The worker dies during
// each test of P1T4; its verifier must charge that test alone and start again
// with a new worker, and the child subreaper of the worker's run must stop
// what it left (no PID namespace takes it down).
#include <chrono>
#include <thread>

// <unistd.h> is not allowed in the grading kit: fork() declared here.
extern "C" int fork();

namespace {
void write_through_null() {
  if (fork() == 0) {  // a child that would outlive the grader
    std::this_thread::sleep_for(std::chrono::seconds(30));
    return;
  }
  volatile int* volatile p = nullptr;  // both volatile, or the compiler drops the store
  *p = 1;
}
}  // namespace
