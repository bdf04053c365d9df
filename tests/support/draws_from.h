#pragma once
// Whether a task that draws random numbers takes them from the generator it
// is given, and only from it (skeleton/render/pathtracer.h: "randomness comes
// only from the Rng passed in"): the renderer seeds one generator per pixel
// and pass, and that is what makes a render the same on any number of
// threads. A generator of the task's own (a static one, std::rand) makes two
// calls from the same state disagree; a copy of the generator passed in
// leaves that generator where it was, so the next estimate would draw the
// very numbers this one used.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "core/rng.h"
#include "core/generator_contract.h"

namespace pt::test {

// `call(rng)` runs the task once with the test's fixed arguments and returns
// its answer (anything with ==). `calls` times in a row: two generators in
// the same state give equal answers and end in the same state, and the
// generator has moved. The task must draw on every call of the test's set-up;
// `calls` must make a generator of the task's own visible: one call where the
// answer is continuous, enough where it is one of a few values (a roulette
// coin of probability 1/2: 64 calls, all alike by chance with probability
// 2^-64). The generators' states are compared exactly (core/generator_contract.h),
// so a correct task never fails.
template <class Call>
::testing::AssertionResult draws_only_from(const Call& call, uint64_t seed, int calls, const std::string& what) {
  Rng a(seed), b(seed);
  for (int k = 0; k < calls; ++k) {
    const Rng before = a;
    const auto answer_a = call(a);
    const auto answer_b = call(b);
    if (!(answer_a == answer_b))
      return ::testing::AssertionFailure()
             << what << ": call " << k + 1 << " gave two different answers from generators in the same state: its "
             << "random numbers must come only from the rng passed in (no generator of its own, no static or global "
                "state, no std::rand)";
    if (!same_bits(a, b))
      return ::testing::AssertionFailure() << what << ": call " << k + 1
                                           << " left two generators that started in the same state in different states";
    const auto drawn = draws_between(before, a);
    if (drawn && *drawn == 0)
      return ::testing::AssertionFailure()
             << what << ": call " << k + 1
             << " did not move the rng passed in: it draws, so it must draw from that rng itself (pass it on by "
                "reference, not a copy, or the next estimate draws the same numbers again)";
    if (!drawn) return ::testing::AssertionFailure() << generator_moved_back(what);
  }
  return ::testing::AssertionSuccess();
}

}  // namespace pt::test
