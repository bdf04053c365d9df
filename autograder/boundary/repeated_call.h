#pragma once
// Runs of one call (README.md beside this file). The statistical tests call an
// estimator or a sampler in a loop with the same arguments, each time with
// the generator the previous call left behind: up to millions of calls, each
// a round trip if asked one at a time. So the verifier asks for a run: the
// worker calls the student's function up to `count` times in a row from the
// generator it was given and returns each answer with the generator's state
// after it. The verifier hands them out while the tests keep asking for the
// same thing from the state the last answer left; anything else (other
// arguments, another generator) starts a new run. A run is what the tests
// would have seen one call at a time, as long as the student's function
// depends only on its arguments and the generator.
//
// That it does is checked here, not believed (support/generator_contract.h):
// every state in a run must be the one before it moved forward, and a share
// of the answers, drawn where the worker cannot predict them, is asked for
// again from the same state, alone, and must come back the same. A function
// that draws from anything else, or keeps state between calls that changes
// its answers, fails the test that called it.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/rng.h"
#include "support/generator_contract.h"
#include "wire.h"

namespace pt::boundary {

// The longest run asked for, and how long the worker may spend on one: a slow
// function answers in shorter runs rather than past what the test needs.
constexpr uint32_t kLongestRun = 1u << 16;
constexpr std::chrono::milliseconds kRunTime{20};

// One answer in kReplayOneIn is replayed on average (every run of that many
// answers or more has one): a function that is not one of its generator is
// caught within the first 31 calls of a loop, at a sixteenth more round trips
// at most (a test of 500,000 different rays makes as many runs of one).
constexpr uint32_t kReplayOneIn = 16;

// Answers compare bit for bit; a struct with padding has a same_answer of its
// own beside it (found by argument-dependent lookup).
template <class Answer>
bool same_answer(const Answer& a, const Answer& b) {
  return test::same_bits(a, b);
}

// The verifier's side. `Answer` is a plain value (a Spectrum, a sample);
// `task` names the function in failure messages.
template <class Answer>
class RepeatedCall {
 public:
  // One answer in `replay_one_in` is replayed on average (0: none, for tests
  // of the runs alone).
  RepeatedCall(Call call, std::string task, uint32_t replay_one_in = kReplayOneIn)
      : call_(call), task_(std::move(task)), replay_one_in_(replay_one_in), replays_(unpredictable_seed()) {}

  // The answer to the call with `args`, from `rng`, which it advances.
  template <class AskWorker>
  Answer next(const Writer& args, Rng& rng, AskWorker&& ask_worker) {
    const bool same_args = args.bytes() == args_;
    if (same_args && at_ > 0 && same(rng, given_) && !same(rng, expected_)) {
      // The last call again, from the state it was given (a test's own
      // replay: support/replayed_draws.h, the contract's draws_only_from).
      // The worker is asked again, alone, and its answer is what the test
      // sees, as in one process: answering from the run would hide from the
      // test's own check a task that is not a function of its generator. The
      // run goes on only if the answer is the one it holds. (A call that drew
      // nothing goes on with its run: its answers must all be the same.)
      std::vector<Answer> again;
      std::vector<Rng> state;
      try {
        read_run(ask_worker(call_, request(given_, 1)), 1, again, state);
      } catch (...) {
        drop_run();
        throw;
      }
      if (!same_answer(again[0], answers_[at_ - 1]) || !same(state[0], states_[at_ - 1])) drop_run();
      rng = state[0];
      expected_ = rng;
      return again[0];
    }
    const bool same_loop = same_args && same(rng, expected_);
    if (!same_loop || at_ == answers_.size()) {
      want_ = same_loop ? std::min(2 * want_, kLongestRun) : 1;
      args_ = args.bytes();
      start_ = rng;
      at_ = 0;
      try {
        read_run(ask_worker(call_, request(start_, want_)), want_, answers_, states_);
        Rng before = start_;
        for (const Rng& after : states_) {
          if (!test::draws_between(before, after))
            throw test::GeneratorContractBroken(test::generator_moved_back(task_));
          before = after;
        }
        maybe_replay(ask_worker);
      } catch (...) {
        drop_run();
        throw;
      }
    }
    given_ = rng;
    rng = states_[at_];
    expected_ = rng;
    test::replayed_by_the_boundary = replay_one_in_ > 0;
    return answers_[at_++];
  }

 private:
  // No run: the next call starts a new one.
  void drop_run() {
    args_.clear();
    answers_.clear();
    states_.clear();
    at_ = 0;
  }

  static bool same(const Rng& a, const Rng& b) { return std::memcmp(&a, &b, sizeof(Rng)) == 0; }

  Writer request(const Rng& rng, uint32_t count) const {
    Writer w;
    w.put_bytes(args_).put(rng).put(count);
    return w;
  }

  static void read_run(const std::string& answer, uint32_t asked, std::vector<Answer>& answers,
                       std::vector<Rng>& states) {
    Reader out(answer);
    const auto n = out.get<uint32_t>();
    if (n < 1 || n > asked) throw LinkBroken("a run of " + std::to_string(n) + " answers to " + std::to_string(asked));
    answers.resize(n);
    states.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
      out.get(answers[i]);
      out.get(states[i]);
    }
    out.finish();
  }

  // Asks again, alone, for one answer of the run just received (with
  // probability n / replay_one_in_ for a run of n), from the state it was
  // asked from: the same answer and state must come back.
  template <class AskWorker>
  void maybe_replay(AskWorker& ask_worker) {
    const auto n = static_cast<uint32_t>(answers_.size());
    if (replay_one_in_ == 0) return;
    if (n < replay_one_in_ && std::uniform_int_distribution<uint32_t>(0, replay_one_in_ - 1)(replays_) >= n) return;
    const uint32_t i = std::uniform_int_distribution<uint32_t>(0, n - 1)(replays_);
    std::vector<Answer> again;
    std::vector<Rng> state;
    try {
      read_run(ask_worker(call_, request(i == 0 ? start_ : states_[i - 1], 1)), 1, again, state);
    } catch (const LinkBroken&) {
      throw;
    } catch (...) {
      // An exception where the first time there was an answer: not the same call.
      again.clear();
    }
    if (again.empty() || !same_answer(again[0], answers_[i]) || !same(state[0], states_[i]))
      throw test::GeneratorContractBroken(test::not_a_function_of_its_generator(task_));
  }

  Call call_;
  std::string task_;
  uint32_t replay_one_in_;
  std::mt19937 replays_;  // which answers are replayed: the worker cannot predict it
  std::string args_;
  std::vector<Answer> answers_;
  std::vector<Rng> states_;
  size_t at_ = 0;
  uint32_t want_ = 1;
  Rng start_, given_, expected_;
};

// The worker's side: reads the generator and the run's length after the
// call's own arguments and writes the run. `once(rng)` is the student's
// function; an exception in its first call is the call's, and a later one
// ends the run early (the next run starts there and meets it first).
template <class Answer, class Once>
void answer_run(Reader& in, Writer& out, Once&& once) {
  auto rng = in.get<Rng>();
  const auto count = std::clamp<uint32_t>(in.get<uint32_t>(), 1, kLongestRun);
  std::vector<std::pair<Answer, Rng>> run;
  run.reserve(std::min<uint32_t>(count, 4096));
  const auto deadline = std::chrono::steady_clock::now() + kRunTime;
  const Answer first = once(rng);  // before the state is copied
  run.emplace_back(first, rng);
  // The clock is read every 16 calls: a fast function costs little more than it.
  while (run.size() < count && (run.size() % 16 != 0 || std::chrono::steady_clock::now() < deadline)) {
    try {
      Answer a = once(rng);
      run.emplace_back(a, rng);
    } catch (const LinkBroken&) {
      throw;
    } catch (...) {
      break;
    }
  }
  out.put(static_cast<uint32_t>(run.size()));
  for (const auto& [answer, state] : run) out.put(answer).put(state);
}

}  // namespace pt::boundary
