// run_with_worker (grade_part.h) in a build without the sandbox (PT_SANDBOX
// off): no process boundary is built there (boundary/ is Linux's), so no part
// is graded across it; a call says why rather than run anything.
#include "process/launcher.h"
#include "run/grade_part.h"

namespace pt::grade {

RunOutcome run_with_worker(Sandbox&, RunRequest request, RunObserver&, const std::string&, RunOutcome& worker_run) {
  for (int fd : {request.link_read, request.link_write})
    if (fd >= 0) Fd(fd).reset();
  worker_run = RunOutcome::not_started("the process boundary needs Linux: this pt-grade has no sandbox (PT_SANDBOX is off)");
  return worker_run;
}

}  // namespace pt::grade
