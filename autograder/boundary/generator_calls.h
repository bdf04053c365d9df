#pragma once
// Calls that take a generator (tasks.def's RNG), asked for in runs and
// checked (README.md beside this file). The statistical tests call an
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
// That it does is checked here, for every such call, not believed
// (core/generator_contract.h): every state in a run must be the one before it
// moved forward, and a share of the answers, drawn where the worker cannot
// predict them, is asked for again from the same state, alone, and must come
// back the same. A function that draws from anything else, or keeps state
// between calls that changes its answers, fails the test that called it.
//
// A call that calls back into the verifier (a pixel's samples, each the
// test's radiance, which a scripted tracer counts) is asked one call at a
// time, so that each callback belongs to the call the test made, and its
// replay is answered from a record of the first time's callbacks (Tape): it
// must make the same callbacks, with the same arguments, in the same order.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "core/generator_contract.h"
#include "core/rng.h"
#include "scoped.h"
#include "wire.h"

namespace pt::boundary {

// The longest run asked for, and how long the worker may spend on one: a slow
// function answers in shorter runs rather than past what the test needs. A
// run's answers together stay far below the largest message.
constexpr uint32_t kLongestRun = 1u << 16;
constexpr std::chrono::milliseconds kRunTime{20};
constexpr size_t kRunBytes = 16u << 20;

// One answer in kReplayOneIn is replayed on average (every run of that many
// answers or more has one): a function that is not one of its generator is
// caught within the first 31 calls of a loop, at a sixteenth more round trips
// at most (a test of 500,000 different rays makes as many runs of one). Calls
// that call back are replayed one in kReplayCallingBackOneIn: the pixel tests
// make tens of calls, not millions.
constexpr uint32_t kReplayOneIn = 16;
constexpr uint32_t kReplayCallingBackOneIn = 4;

// The callbacks of a call, recorded so that the call can be replayed without
// calling the test's functions again.
struct Tape {
  struct Callback {
    Call call;
    std::string args, answer;
  };
  std::vector<Callback> callbacks;
  bool playing = false;
  size_t at = 0;
  bool differs = false;
};
inline thread_local Tape* g_tape = nullptr;

// Serves a callback of the verifier's with `serve`, or while a tape plays,
// from the tape. `args` are the callback's arguments as received.
template <class Serve>
void through_tape(Call call, std::string_view args, Writer& result, Serve&& serve) {
  Tape* tape = g_tape;
  if (!tape) return serve(result);
  if (!tape->playing) {
    Writer answer;
    serve(answer);
    tape->callbacks.push_back({call, std::string(args), answer.bytes()});
    result.put_bytes(answer.bytes());
    return;
  }
  if (tape->at < tape->callbacks.size() && tape->callbacks[tape->at].call == call &&
      tape->callbacks[tape->at].args == args) {
    result.put_bytes(tape->callbacks[tape->at++].answer);
    return;
  }
  // Not the callback the first call made here: the replay differs. It gets
  // an answer of the right shape so that it can end.
  tape->differs = true;
  serve(result);
}

// The verifier's side of one row: the answers (the bytes of the return value
// and of what comes back with it) of the calls a test makes.
class GeneratorCalls {
 public:
  // `task` names the function in failure messages; `calls_back`: one call at
  // a time, replays from a tape; `replay_one_in` 0 replays nothing (for tests
  // of the runs alone).
  GeneratorCalls(Call call, std::string task, bool calls_back, uint32_t replay_one_in)
      : call_(call),
        task_(std::move(task)),
        calls_back_(calls_back),
        longest_(calls_back ? 1 : kLongestRun),
        replay_one_in_(replay_one_in),
        replays_(unpredictable_seed()) {}
  GeneratorCalls(Call call, std::string task, bool calls_back)
      : GeneratorCalls(call, std::move(task), calls_back, calls_back ? kReplayCallingBackOneIn : kReplayOneIn) {}

  // The answer to the call with `args`, from `rng`, which it advances; valid
  // until the next call. `ask_worker(call, request)` returns the worker's
  // answer to a request.
  template <class AskWorker>
  std::string_view next(const Writer& args, Rng& rng, AskWorker&& ask_worker) {
    const bool same_args = args.bytes() == args_;
    if (same_args && at_ > 0 && same(rng, given_) && !same(rng, expected_)) return again(rng, ask_worker);
    const bool same_loop = same_args && same(rng, expected_);
    if (!same_loop || at_ == states_.size()) {
      want_ = same_loop ? std::min(2 * want_, longest_) : 1;
      args_ = args.bytes();
      start_ = rng;
      at_ = 0;
      try {
        Tape tape;
        {
          const Scoped<Tape*> record(g_tape, calls_back_ ? &tape : nullptr);
          read_run(ask_worker(call_, request(start_, want_)), want_, run_, ends_, states_);
        }
        Rng before = start_;
        for (const Rng& after : states_) {
          if (!draws_between(before, after)) throw GeneratorContractBroken(generator_moved_back(task_));
          before = after;
        }
        maybe_replay(ask_worker, tape);
      } catch (...) {
        drop_run();
        throw;
      }
    }
    given_ = rng;
    rng = states_[at_];
    expected_ = rng;
    replayed_by_the_boundary = replay_one_in_ > 0;
    return answer(run_, ends_, at_++);
  }

 private:
  // The last call again, from the state it was given (a test's own replay:
  // tests/support/replayed_draws.h, the contract's draws_only_from). The
  // worker is asked again, alone, and its answer is what the test sees, as in
  // one process: answering from the run would hide from the test's own check
  // a task that is not a function of its generator. The run goes on only if
  // the answer is the one it holds. (A call that drew nothing goes on with
  // its run: its answers must all be the same.)
  template <class AskWorker>
  std::string_view again(Rng& rng, AskWorker& ask_worker) {
    std::vector<uint32_t> ends;
    std::vector<Rng> state;
    try {
      read_run(ask_worker(call_, request(given_, 1)), 1, again_, ends, state);
    } catch (...) {
      drop_run();
      throw;
    }
    if (answer(again_, ends, 0) != answer(run_, ends_, at_ - 1) || !same(state[0], states_[at_ - 1])) drop_run();
    rng = state[0];
    expected_ = rng;
    return answer(again_, ends, 0);
  }

  // No run: the next call starts a new one.
  void drop_run() {
    args_.clear();
    run_.clear();
    ends_.clear();
    states_.clear();
    at_ = 0;
  }

  static bool same(const Rng& a, const Rng& b) { return std::memcmp(&a, &b, sizeof(Rng)) == 0; }

  static std::string_view answer(const std::string& run, const std::vector<uint32_t>& ends, size_t i) {
    const uint32_t from = i == 0 ? 0 : ends[i - 1];
    return std::string_view(run).substr(from, ends[i] - from);
  }

  Writer request(const Rng& rng, uint32_t count) const {
    Writer w;
    w.put_bytes(args_).put(rng).put(count);
    return w;
  }

  // A run as answer_run writes it: its length, then each answer (its bytes)
  // and the generator's state after it.
  static void read_run(const std::string& message, uint32_t asked, std::string& run, std::vector<uint32_t>& ends,
                       std::vector<Rng>& states) {
    Reader in(message);
    const auto n = in.get<uint32_t>();
    if (n < 1 || n > asked) throw LinkBroken("a run of " + std::to_string(n) + " answers to " + std::to_string(asked));
    run.clear();
    ends.resize(n);
    states.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
      run += in.get_view(kRunBytes);
      ends[i] = static_cast<uint32_t>(run.size());
      in.get(states[i]);
    }
    in.finish();
  }

  // Asks again, alone, for one answer of the run just received (with
  // probability n / replay_one_in_ for a run of n), from the state it was
  // asked from: the same answer and state must come back, and the same
  // callbacks (those of a run of one, taped).
  template <class AskWorker>
  void maybe_replay(AskWorker& ask_worker, Tape& tape) {
    const auto n = static_cast<uint32_t>(states_.size());
    if (replay_one_in_ == 0) return;
    if (n < replay_one_in_ && std::uniform_int_distribution<uint32_t>(0, replay_one_in_ - 1)(replays_) >= n) return;
    const uint32_t i = std::uniform_int_distribution<uint32_t>(0, n - 1)(replays_);
    std::string bytes;
    std::vector<uint32_t> ends;
    std::vector<Rng> state;
    tape.playing = true;
    try {
      const Scoped<Tape*> play(g_tape, calls_back_ ? &tape : nullptr);
      read_run(ask_worker(call_, request(i == 0 ? start_ : states_[i - 1], 1)), 1, bytes, ends, state);
    } catch (const LinkBroken&) {
      throw;
    } catch (...) {
      // An exception where the first time there was an answer: not the same call.
      state.clear();
    }
    if (state.empty() || answer(bytes, ends, 0) != answer(run_, ends_, i) || !same(state[0], states_[i]) ||
        tape.differs || tape.at != tape.callbacks.size())
      throw GeneratorContractBroken(not_a_function_of_its_generator(task_));
  }

  Call call_;
  std::string task_;
  bool calls_back_;
  uint32_t longest_;
  uint32_t replay_one_in_;
  std::mt19937 replays_;  // which answers are replayed: the worker cannot predict it
  std::string args_;
  std::string run_, again_;     // the answers' bytes, end to end
  std::vector<uint32_t> ends_;  // where each answer of run_ ends
  std::vector<Rng> states_;
  size_t at_ = 0;
  uint32_t want_ = 1;
  Rng start_, given_, expected_;
};

// The worker's side: reads the generator and the run's length after the
// call's own arguments and writes the run. `once(rng, answer)` calls the
// student's function and writes its answer; an exception in its first call is
// the call's, and a later one ends the run early (the next run starts there
// and meets it first).
template <class Once>
void answer_run(Reader& in, Writer& out, Once&& once) {
  auto rng = in.get<Rng>();
  const auto count = std::clamp<uint32_t>(in.get<uint32_t>(), 1, kLongestRun);
  const size_t start = out.size();
  out.put(uint32_t{0});  // the run's length, known at its end
  uint32_t n = 0;
  // Each answer as put_string writes one, its length patched in once written.
  auto one = [&] {
    const size_t at = out.size();
    out.put(uint32_t{0});
    try {
      once(rng, out);
    } catch (...) {
      out.truncate(at);
      throw;
    }
    out.patch(at, static_cast<uint32_t>(out.size() - at - sizeof(uint32_t)));
    out.put(rng);
    ++n;
  };
  const auto deadline = std::chrono::steady_clock::now() + kRunTime;
  one();  // before the state is copied
  // The clock is read every 16 calls: a fast function costs little more than it.
  while (n < count && out.size() - start < kRunBytes &&
         (n % 16 != 0 || std::chrono::steady_clock::now() < deadline)) {
    try {
      one();
    } catch (const LinkBroken&) {
      throw;
    } catch (...) {
      break;
    }
  }
  out.patch(start, n);
}

}  // namespace pt::boundary
