// The process boundary's run (grade_part.h: run_with_worker): a verifier and
// its worker, each in its own sandbox run, on one CPU. Built with the sandbox
// (PT_SANDBOX); worker_run_unavailable.cpp stands in for it elsewhere.
#include <sched.h>

#include <cerrno>
#include <cstring>
#include <optional>

#include "boundary/one_cpu.h"
#include "process/launcher.h"
#include "run/grade_part.h"

namespace pt::grade {

RunOutcome run_with_worker(Sandbox& sandbox, RunRequest request, RunObserver& watch, const std::string& worker,
                           RunOutcome& worker_run) {
  Pipe to_worker, from_worker;
  if (!to_worker.open() || !from_worker.open())
    return RunOutcome::not_started(std::string("pipe: ") + std::strerror(errno));
  RunRequest w{worker, {}, "", ""};
  w.link_read = to_worker.read.release();
  w.link_write = from_worker.write.release();
  request.args.push_back("--pt_worker_fds=5,6");
  request.link_read = from_worker.read.release();
  request.link_write = to_worker.write.release();
  // Both runs inherit this thread's CPU at their clone (restored after them).
  cpu_set_t before;
  const bool restore = ::sched_getaffinity(0, sizeof before, &before) == 0;
  const std::optional<cpu_set_t> cpu = boundary::one_cpu();
  if (cpu) ::sched_setaffinity(0, sizeof *cpu, &*cpu);
  RunOutcome run = sandbox.run(request, watch, &w, &worker_run);
  if (cpu && restore) ::sched_setaffinity(0, sizeof before, &before);
  return run;
}

}  // namespace pt::grade
