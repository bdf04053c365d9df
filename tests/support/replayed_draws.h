#pragma once
// How the statistical tests call a task that draws from a generator: as what
// it is specified to be, a function of its arguments and of the generator
// passed in (core/generator_contract.h). Each call must move the generator forward,
// and one call in kReplayedOneIn is made a second time from a copy of the same
// state and must give the same answer and leave the same state. A task whose
// randomness comes from anywhere else (a static generator, std::rand, a cache
// of earlier answers that it averages) fails the test that called it, saying
// so, in the tests' own process as across the grader's boundary, which
// replays calls of its own where the worker cannot predict them
// (autograder/boundary/generator_calls.h): a call it answers that way is not
// replayed here again.
//
// A test's power does not depend on how many numbers a task draws: only the
// states before and after a call are compared.
#include <cstdint>
#include <string>
#include <type_traits>

#include "core/generator_contract.h"
#include "support/seed.h"

namespace pt::test {

// A cache that averages its last N answers is caught at the first replay after
// its second call; 1 in 16 doubles the cost of one call in 16.
constexpr uint32_t kReplayedOneIn = 16;

// Which calls are replayed: a generator of the helper's own, seeded like the
// tests (shifted by --pt_seed).
inline bool replay_this_call() {
  thread_local Rng which(seed(0x2e91a7));
  return which.uniform() * kReplayedOneIn < 1.0;
}

// `task(rng)` makes the call, e.g.
//   replayed("estimate_direct_lighting_importance", rng,
//            [&](Rng& r) { return tracer.estimate_direct_lighting_importance(ray, isect, r); });
// and returns a plain value without padding (a Spectrum, a struct of doubles).
// `name` names the task in the failure's message.
template <class Task>
auto replayed(const std::string& name, Rng& rng, Task&& task) -> std::invoke_result_t<Task&, Rng&> {
  const Rng given = rng;
  replayed_by_the_boundary = false;
  const auto answer = task(rng);
  if (!draws_between(given, rng)) throw GeneratorContractBroken(generator_moved_back(name));
  if (!replayed_by_the_boundary && replay_this_call()) {
    Rng again = given;
    bool same = false;
    try {
      same = same_bits(task(again), answer) && same_bits(again, rng);
    } catch (...) {
      // An exception where the first call answered: not the same call.
    }
    if (!same) throw GeneratorContractBroken(not_a_function_of_its_generator(name));
  }
  return answer;
}

}  // namespace pt::test
