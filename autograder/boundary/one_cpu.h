#pragma once
// One CPU for a verifier and its worker. They take turns (each waits for the
// other's answer), and on a virtual machine a wake-up on the other CPU costs
// far more than the turn itself: Part 1's suite took 0.24 s on one CPU against
// 1.3-2.0 s spread over two, and Part 4's Cornell-box region test (500,000
// round trips) 2.9 s against 24.5 s, past the test main's 20 s limit
// (measured side by side on the 2-core machine). pt-grade pins both runs
// (grade_part.cpp); a verifier that starts its worker itself (--pt_worker)
// pins itself and so the worker it starts (verifier_link.cpp). The CPU is the
// one this process runs on when it asks, which the scheduler chose with the
// others' load in view: two runs side by side (ctest -j2) then rarely share
// one CPU while the other idles, as a pick by process id did half the time.
#include <sched.h>

#include <optional>

namespace pt::boundary {

inline std::optional<cpu_set_t> one_cpu() {
  cpu_set_t allowed;
  if (::sched_getaffinity(0, sizeof allowed, &allowed) != 0 || CPU_COUNT(&allowed) <= 1) return std::nullopt;
  const int here = ::sched_getcpu();
  if (here < 0 || here >= CPU_SETSIZE || !CPU_ISSET(here, &allowed)) return std::nullopt;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(here, &one);
  return one;
}

}  // namespace pt::boundary
