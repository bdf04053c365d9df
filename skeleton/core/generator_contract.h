#pragma once
// What every task that takes a generator is specified to be: a function of its
// arguments and of the generator passed in, which it moves forward by the
// numbers it draws and in no other way. Two checks follow, made wherever such
// a task is called (the tests' own replays in one process,
// tests/support/replayed_draws.h; the grader's process boundary across it)
// and failing with the messages below:
//   - the state handed back is the given one advanced by a bounded number of
//     draws (not moved back, not replaced);
//   - the same call from a copy of the same state gives the same answer and
//     the same state (no randomness from anywhere else).
// In the framework because both the tests and the grader's boundary check it.
#include <cstdint>
#include <cstring>
#include <optional>
#include <pcg_random.hpp>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/rng.h"

namespace pt {

// More draws than any one call of the course makes (2^40: hours of drawing
// and nothing else). A generator moved back by k reads as 2^64 - k draws
// forward, and a state picked at random lies this close ahead with
// probability 2^-24: both fail.
constexpr uint64_t kMostDrawsInOneCall = uint64_t(1) << 40;

// How many numbers take `before` to `after`, if `after` is `before` moved
// forward by at most kMostDrawsInOneCall; nothing otherwise (another stream,
// an earlier state, an unrelated one).
inline std::optional<uint64_t> draws_between(const Rng& before, const Rng& after) {
  static_assert(sizeof(Rng) == sizeof(pcg32) && std::is_trivially_copyable_v<Rng>, "Rng is its PCG engine");
  pcg32 from, to;
  std::memcpy(static_cast<void*>(&from), &before, sizeof from);
  std::memcpy(static_cast<void*>(&to), &after, sizeof to);
  try {
    const uint64_t n = to - from;  // pcg-cpp's distance: throws for another stream
    if (n <= kMostDrawsInOneCall) return n;
  } catch (const std::logic_error&) {
  }
  return std::nullopt;
}

// A task broke the contract above; thrown where it is seen, so that the test
// that made the call fails with this message.
struct GeneratorContractBroken : std::logic_error {
  using std::logic_error::logic_error;
};

inline std::string generator_moved_back(const std::string& task) {
  return task + " handed back a generator that is not the one passed in moved forward: it was moved backwards or "
                "replaced (a task may only draw from the generator it is given)";
}

inline std::string not_a_function_of_its_generator(const std::string& task) {
  return task + ": its answer is not a function of its arguments and the generator passed in (randomness from "
                "somewhere else: a static generator, std::rand, state kept between calls): the same call from a "
                "copy of the same generator gave another answer";
}

// Answers compare bit for bit (a NaN is the same answer as itself). For
// structs without padding; a struct with padding gets a same_answer of its own.
template <class Answer>
bool same_bits(const Answer& a, const Answer& b) {
  static_assert(std::is_trivially_copyable_v<Answer>, "an answer is a plain value");
  return std::memcmp(&a, &b, sizeof(Answer)) == 0;
}

// Set by the grader's boundary when it answers a call from a run that it
// checks itself, by replays the worker cannot predict
// (autograder/boundary/generator_calls.h); the tests' own replays then leave
// that call to it. Across the boundary a replay is a round trip: the
// tests' own replays on top of the boundary's were most of the time of Part
// 3's and Part 4's statistical tests there, and checked nothing more.
inline thread_local bool replayed_by_the_boundary = false;

}  // namespace pt
