// The process boundary's run (grade_part.h: run_with_worker): a verifier and
// its worker, each in its own sandbox run, on one CPU. Built with the sandbox
// (PT_SANDBOX); worker_run_unavailable.cpp stands in for it elsewhere.
#include <poll.h>
#include <sched.h>
#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>

#include "boundary/one_cpu.h"
#include "process/launcher.h"
#include "run/grade_part.h"
#include "run/run_outcome.h"

namespace pt::grade {
namespace {

// The worker's run ends a second after its verifier's (the grader closes the
// write end of `verifier_done`), or sooner, by itself: a worker that has
// already died is seen dead, not stopped, and one still running reads the end
// of its link and leaves.
class WorkerWatch : public RunObserver {
 public:
  explicit WorkerWatch(int verifier_done) : verifier_done_(verifier_done) {}
  void on_channel(std::string_view) override {}
  Deadline deadline() const override {
    if (ends_ == Clock::time_point::max()) {
      pollfd p{verifier_done_, POLLIN, 0};
      if (::poll(&p, 1, 0) > 0) ends_ = Clock::now() + std::chrono::seconds(1);
    }
    return {std::min(ends_, Clock::now() + std::chrono::hours(1)), 0};
  }

 private:
  int verifier_done_;
  mutable Clock::time_point ends_ = Clock::time_point::max();
};

}  // namespace

// The worker's run is driven by a helper process, not a thread: the sandbox
// clones its processes with a raw clone(), which in a process with a second
// thread could copy a lock that thread holds (malloc's) and hang the copy.
RunOutcome run_with_worker(Sandbox& sandbox, RunRequest request, RunObserver& watch, const std::string& worker,
                           RunOutcome& worker_run) {
  Pipe to_worker, from_worker, done, outcome;
  for (Pipe* p : {&to_worker, &from_worker, &done, &outcome})
    if (!p->open()) return RunOutcome::not_started(std::string("pipe: ") + std::strerror(errno));
  // Both runs inherit the CPU at their clone: the helper's for the worker,
  // this thread's (restored after the run) for the verifier.
  cpu_set_t before;
  const bool restore = ::sched_getaffinity(0, sizeof before, &before) == 0;
  const std::optional<cpu_set_t> cpu = boundary::one_cpu();
  LaunchOptions launch;
  launch.parent_death_signal = SIGKILL;
  launch.child_ends = {to_worker.read.get(), from_worker.write.get(), done.read.get(), outcome.write.get()};
  Child helper(launch, [&] {
    if (cpu) ::sched_setaffinity(0, sizeof *cpu, &*cpu);
    for (Fd* fd : {&to_worker.write, &from_worker.read, &done.write, &outcome.read}) fd->reset();
    RunRequest w{worker, {}, "", ""};
    w.link_read = to_worker.read.release();
    w.link_write = from_worker.write.release();
    WorkerWatch worker_watch(done.read.get());
    write_outcome(outcome.write.get(), sandbox.run(w, worker_watch));
    ::_exit(0);
  });
  for (Fd* fd : {&to_worker.read, &from_worker.write, &done.read, &outcome.write}) fd->release();  // closed by the launch
  if (!helper.started()) return RunOutcome::not_started(std::string("fork: ") + std::strerror(helper.start_error()));
  request.args.push_back("--pt_worker_fds=5,6");
  request.link_read = from_worker.read.release();
  request.link_write = to_worker.write.release();
  if (cpu) ::sched_setaffinity(0, sizeof *cpu, &*cpu);
  RunOutcome run = sandbox.run(request, watch);
  if (cpu && restore) ::sched_setaffinity(0, sizeof before, &before);
  done.write.reset();
  worker_run = read_outcome(outcome.read.get());
  helper.wait();
  return run;
}

}  // namespace pt::grade
