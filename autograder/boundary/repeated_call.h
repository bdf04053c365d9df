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
#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>
#include <vector>

#include "core/rng.h"
#include "wire.h"

namespace pt::boundary {

// The longest run asked for, and how long the worker may spend on one: a slow
// function answers in shorter runs rather than past what the test needs.
constexpr uint32_t kLongestRun = 1u << 16;
constexpr std::chrono::milliseconds kRunTime{20};

// The verifier's side. `Answer` is a plain value (a Spectrum, a sample).
template <class Answer>
class RepeatedCall {
 public:
  explicit RepeatedCall(Call call) : call_(call) {}

  // The answer to the call with `args`, from `rng`, which it advances.
  template <class AskWorker>
  Answer next(const Writer& args, Rng& rng, AskWorker&& ask_worker) {
    const bool same_loop = args.bytes() == args_ && same(rng, expected_);
    if (!same_loop || at_ == answers_.size()) {
      want_ = same_loop ? std::min(2 * want_, kLongestRun) : 1;
      args_ = args.bytes();
      Writer request;
      request.put_bytes(args_).put(rng).put(want_);
      const std::string answer = ask_worker(call_, request);
      Reader out(answer);
      const auto n = out.get<uint32_t>();
      if (n < 1 || n > want_) throw LinkBroken("a run of " + std::to_string(n) + " answers to " + std::to_string(want_));
      answers_.resize(n);
      states_.resize(n);
      for (uint32_t i = 0; i < n; ++i) {
        out.get(answers_[i]);
        out.get(states_[i]);
      }
      out.finish();
      at_ = 0;
    }
    rng = states_[at_];
    expected_ = rng;
    return answers_[at_++];
  }

 private:
  static bool same(const Rng& a, const Rng& b) { return std::memcmp(&a, &b, sizeof(Rng)) == 0; }

  Call call_;
  std::string args_;
  std::vector<Answer> answers_;
  std::vector<Rng> states_;
  size_t at_ = 0;
  uint32_t want_ = 1;
  Rng expected_;
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
