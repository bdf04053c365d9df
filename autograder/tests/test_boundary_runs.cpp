// Runs of one call across the boundary (boundary/generator_calls.h): the
// answers a test receives from a run are those it would have received one
// call at a time, a run is only used while the test repeats the same call from
// the state the last answer left, and a worker that answers more than it was
// asked breaks the link. What the runs check of the answers: every state moves
// forward, and a replayed answer is the same (core/generator_contract.h).
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>
#include <vector>

#include "generator_calls.h"

namespace pt::boundary {
namespace {

// A stand-in for a student's estimator: depends on its argument and on the
// random numbers it draws (how many depends on the first one).
double estimator(double arg, Rng& rng) {
  double v = arg + rng.uniform();
  if (v - arg < 0.5) v += rng.uniform();
  return v;
}

// The worker's side, answering in-process: what a run request would get.
struct FakeWorker {
  std::vector<uint32_t> asked;  // length of each run asked for
  const Rng* throw_from = nullptr;  // the generator's state at which the function throws
  uint32_t extra = 0;           // answers beyond the asked-for run (a hostile worker)
  std::function<double(double, Rng&)> function = estimator;  // the student's
  std::string operator()(Call, const Writer& request) {
    {
      Reader peek(request.bytes());
      peek.get<double>();
      peek.get<Rng>();
      asked.push_back(peek.get<uint32_t>());
    }
    Reader in(request.bytes());
    const auto arg = in.get<double>();
    Writer run;
    answer_run(in, run, [&](Rng& rng, Writer& answer) {
      if (throw_from && std::memcmp(&rng, throw_from, sizeof(Rng)) == 0) throw std::runtime_error("the student's function threw");
      answer.put(function(arg, rng));
    });
    in.finish();
    if (extra == 0) return run.bytes();
    // A hostile worker: says it sends more answers than were asked for, and does.
    Reader r(run.bytes());
    Writer out;
    out.put(r.get<uint32_t>() + extra).put_bytes(run.bytes().substr(sizeof(uint32_t)));
    Writer zero;
    zero.put(0.0);
    for (uint32_t i = 0; i < extra; ++i) out.put_string(zero.bytes()).put(Rng());
    return out.bytes();
  }
};

Writer args_of(double arg) {
  Writer w;
  w.put(arg);
  return w;
}

// The runs of one row whose answer is a double.
class Runs {
 public:
  Runs(Call call, const std::string& task) : calls_(call, task, false) {}
  Runs(Call call, const std::string& task, uint32_t replay_one_in) : calls_(call, task, false, replay_one_in) {}
  template <class AskWorker>
  double next(const Writer& args, Rng& rng, AskWorker&& ask) {
    Reader r(calls_.next(args, rng, ask));
    const auto value = r.get<double>();
    r.finish();
    return value;
  }

 private:
  GeneratorCalls calls_;
};

TEST(BoundaryRuns, AnswersAreThoseOfOneCallAtATime) {
  FakeWorker worker;
  Runs runs(Call::DirectImportance, "the estimator", 0);
  Rng across(7), here(7);
  for (int i = 0; i < 5000; ++i) {
    const double got = runs.next(args_of(0.25), across, [&](Call c, const Writer& w) { return worker(c, w); });
    const double want = estimator(0.25, here);
    ASSERT_EQ(got, want) << "call " << i;
    ASSERT_EQ(std::memcmp(&across, &here, sizeof(Rng)), 0) << "the generator's state after call " << i;
  }
  // Runs double from one call: 1 + 2 + ... + 4096 covers 5000 calls in 13.
  EXPECT_LE(worker.asked.size(), 13u);
  EXPECT_EQ(worker.asked.front(), 1u);
}

TEST(BoundaryRuns, OtherArgumentsOrAnotherGeneratorStartANewRun) {
  FakeWorker worker;
  Runs runs(Call::DirectImportance, "the estimator", 0);
  auto ask = [&](Call c, const Writer& w) { return worker(c, w); };
  Rng rng(1);
  for (int i = 0; i < 20; ++i) runs.next(args_of(0.25), rng, ask);
  const size_t runs_so_far = worker.asked.size();
  Rng other(1), expected(1);
  EXPECT_EQ(runs.next(args_of(0.25), other, ask), estimator(0.25, expected)) << "a generator back at its start";
  EXPECT_EQ(worker.asked.size(), runs_so_far + 1);
  EXPECT_EQ(worker.asked.back(), 1u);
  Rng again = other;
  EXPECT_EQ(runs.next(args_of(0.75), other, ask), estimator(0.75, again)) << "another argument";
  EXPECT_EQ(worker.asked.size(), runs_so_far + 2);
  EXPECT_EQ(worker.asked.back(), 1u);
}

TEST(BoundaryRuns, AnExceptionIsTheCallsThatMeetsIt) {
  // The function throws from the state it is called with the 11th time:
  // inside the run of 8 that starts at the 8th call.
  Rng eleventh(3);
  for (int i = 0; i < 10; ++i) estimator(0.5, eleventh);
  FakeWorker worker;
  worker.throw_from = &eleventh;
  Runs runs(Call::DirectImportance, "the estimator");
  auto ask = [&](Call c, const Writer& w) { return worker(c, w); };
  Rng rng(3), here(3);
  int answered = 0;
  try {
    for (; answered < 100; ++answered) {
      ASSERT_EQ(runs.next(args_of(0.5), rng, ask), estimator(0.5, here)) << "call " << answered;
    }
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "the student's function threw");
  }
  EXPECT_EQ(answered, 10) << "the calls before the one that threw are answered, and that one throws";
}

TEST(BoundaryRuns, AWorkerThatAnswersMoreThanAskedBreaksTheLink) {
  FakeWorker worker;
  worker.extra = 1;
  Runs runs(Call::DirectImportance, "the estimator");
  Rng rng(5);
  EXPECT_THROW(runs.next(args_of(0.5), rng, [&](Call c, const Writer& w) { return worker(c, w); }), LinkBroken);
}

TEST(BoundaryRuns, AWorkerThatAnswersNothingBreaksTheLink) {
  Runs runs(Call::DirectImportance, "the estimator");
  Rng rng(5);
  Writer nothing;
  nothing.put(uint32_t{0});
  EXPECT_THROW(runs.next(args_of(0.5), rng, [&](Call, const Writer&) { return nothing.bytes(); }), LinkBroken);
}

// ---- What the runs check of the answers


auto asks(FakeWorker& worker) {
  return [&worker](Call c, const Writer& w) { return worker(c, w); };
}

// Calls the estimator `calls` times in a loop, as a statistical test does;
// the message of the contract broken, or "" if none was.
std::string loop(Runs& runs, FakeWorker& worker, int calls, double arg = 0.25) {
  Rng rng(11);
  try {
    for (int i = 0; i < calls; ++i) runs.next(args_of(arg), rng, asks(worker));
  } catch (const GeneratorContractBroken& e) {
    return e.what();
  }
  return "";
}

TEST(BoundaryRuns, AnHonestFunctionPassesEveryReplay) {
  FakeWorker worker;
  Runs runs(Call::DirectImportance, "the estimator", 1);  // every run has one replayed
  EXPECT_EQ(loop(runs, worker, 5000), "");
  EXPECT_EQ(loop(runs, worker, 50, 0.75), "") << "other arguments";
}

TEST(BoundaryRuns, AGeneratorMovedBackFailsTheCall) {
  // The shadow-acne estimator's trick: hand back the state from before the
  // test's own draws, so that the test draws the same input again.
  FakeWorker worker;
  Runs runs(Call::DirectImportance, "the estimator", 0);
  Rng rng(3);
  rng.uniform();  // the test's input
  // Moved back to where it was one draw before it was passed in.
  worker.function = [](double arg, Rng& rng) {
    const double v = estimator(arg, rng);
    Rng back(3);
    rng = back;
    return v;
  };
  try {
    runs.next(args_of(0.5), rng, asks(worker));
    FAIL() << "a generator handed back one draw behind the one passed in was taken";
  } catch (const GeneratorContractBroken& e) {
    EXPECT_NE(std::string(e.what()).find("the estimator handed back a generator"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("moved backwards or replaced"), std::string::npos) << e.what();
  }
}

TEST(BoundaryRuns, AGeneratorReplacedFailsTheCall) {
  FakeWorker worker;
  worker.function = [](double arg, Rng& rng) {
    const double v = estimator(arg, rng);
    rng = Rng(12345, 7);  // another stream
    return v;
  };
  Runs runs(Call::DirectImportance, "the estimator", 0);
  EXPECT_NE(loop(runs, worker, 3).find("moved backwards or replaced"), std::string::npos);
  // The same stream, a state that is not a few draws ahead.
  worker.function = [](double arg, Rng& rng) {
    const double v = estimator(arg, rng);
    rng = Rng(999);
    return v;
  };
  Runs again(Call::DirectImportance, "the estimator", 0);
  EXPECT_NE(loop(again, worker, 3).find("moved backwards or replaced"), std::string::npos);
}

TEST(BoundaryRuns, AGeneratorLeftAloneIsAllowed) {
  // Zero draws is moving forward by zero (an estimator of a point light).
  FakeWorker worker;
  worker.function = [](double arg, Rng&) { return arg * 2.0; };
  Runs runs(Call::DirectImportance, "the estimator", 1);
  EXPECT_EQ(loop(runs, worker, 1000), "");
}

TEST(BoundaryRuns, RandomnessFromElsewhereFailsAReplay) {
  // A static generator that leaves the one passed in alone, std::rand: the
  // same call from the same state gives another answer. A run of 16 or more
  // always has one of its answers replayed, so 31 calls (runs of 1, 2, 4, 8,
  // 16) are enough.
  FakeWorker worker;
  worker.function = [](double arg, Rng&) {
    static Rng own(1);
    return arg + own.uniform();
  };
  Runs runs(Call::DiffuseSampleF, "DiffuseBSDF::sample_f");
  EXPECT_NE(loop(runs, worker, 31).find("DiffuseBSDF::sample_f: its answer is not a function of its arguments and the "
                                        "generator passed in"),
            std::string::npos);
  worker.function = [](double arg, Rng& rng) { return estimator(arg, rng) + std::rand() * 1e-12; };
  Runs with_rand(Call::DirectImportance, "the estimator");
  EXPECT_NE(loop(with_rand, worker, 31).find("not a function of its arguments"), std::string::npos);
}

TEST(BoundaryRuns, AnAverageOfEarlierAnswersFailsAReplay) {
  // One sample per call, returned as the mean of the last 16 for the same
  // argument: the variance falls as if 16 were taken, and each answer is a
  // fair draw of a mean. Asked again from the same state, it is another mean.
  FakeWorker worker;
  std::map<double, std::vector<double>> last;
  worker.function = [&last](double arg, Rng& rng) {
    auto& raw = last[arg];
    raw.push_back(estimator(arg, rng));
    if (raw.size() > 16) raw.erase(raw.begin());
    double sum = 0;
    for (double x : raw) sum += x;
    return sum / double(raw.size());
  };
  Runs runs(Call::DirectImportance, "the estimator");
  EXPECT_NE(loop(runs, worker, 31).find("not a function of its arguments"), std::string::npos);
}

TEST(BoundaryRuns, ATestsOwnReplayAsksTheWorkerAgain) {
  // support/replayed_draws.h and the contract's draws_only_from call again
  // from a copy of the state the last call was given. The worker is asked
  // again, alone (one more request each time), and an honest function's run
  // goes on: the same answer and state as the first time.
  FakeWorker worker;
  Runs runs(Call::DirectImportance, "the estimator", 0);
  Rng rng(8);
  for (int i = 0; i < 20; ++i) {
    const Rng copy = rng;
    const double first = runs.next(args_of(0.5), rng, asks(worker));
    Rng again = copy;
    const size_t asked = worker.asked.size();
    EXPECT_EQ(runs.next(args_of(0.5), again, asks(worker)), first) << "call " << i;
    EXPECT_EQ(std::memcmp(&again, &rng, sizeof(Rng)), 0) << "call " << i;
    EXPECT_EQ(worker.asked.size(), asked + 1) << "call " << i;
  }
}

TEST(BoundaryRuns, ATestsOwnReplaySeesAFunctionOfSomethingElse) {
  // A static generator answers a test's own replay with another value, as it
  // would in one process: the test's check, not a memory of the run, decides.
  FakeWorker worker;
  worker.function = [](double arg, Rng& rng) {
    static Rng own(3);
    rng.uniform();
    return arg + own.uniform();
  };
  Runs runs(Call::DiffuseSampleF, "DiffuseBSDF::sample_f", 0);
  Rng rng(8);
  const Rng copy = rng;
  const double first = runs.next(args_of(0.5), rng, asks(worker));
  Rng again = copy;
  EXPECT_NE(runs.next(args_of(0.5), again, asks(worker)), first);
}

// ---- Calls that call back (a pixel's samples): one call a run, its replay
// answered from a tape of the first time's callbacks

// The verifier's callback as the link serves it: through the tape of a call
// being replayed. It counts what the test's own function is asked, as a
// scripted tracer counts its samples.
struct Callbacks {
  int served = 0;
  double serve(double x) {
    Writer args, answer;
    args.put(x);
    through_tape(Call::EstRadiance, args.bytes(), answer, [&](Writer& a) {
      ++served;
      a.put(2.0 * x);
    });
    Reader r(answer.bytes());
    return r.get<double>();
  }
};

// A pixel loop: n samples, each a callback with a number drawn from the
// generator; `extra` is added to the callbacks' arguments (a function of
// something else when it changes between calls).
std::string pixel_run(const Writer& request, Callbacks& callbacks, const std::function<double()>& extra) {
  Reader in(request.bytes());
  const auto n = in.get<int>();
  Writer out;
  answer_run(in, out, [&](Rng& rng, Writer& answer) {
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += callbacks.serve(rng.uniform() + extra());
    answer.put(sum);
  });
  in.finish();
  return out.bytes();
}

TEST(BoundaryRuns, ACallThatCallsBackIsReplayedFromItsTape) {
  // Every call replayed (one in one): the replay's callbacks are answered
  // from the record, so the test's function is asked only for the calls it
  // made; each call is a run of one.
  Callbacks callbacks;
  GeneratorCalls runs(Call::RaytracePixel, "PathTracer::raytrace_pixel", true, 1);
  Writer args;
  args.put(8);
  Rng rng(4);
  int requests = 0;
  for (int i = 0; i < 10; ++i) {
    runs.next(args, rng, [&](Call, const Writer& w) {
      ++requests;
      return pixel_run(w, callbacks, [] { return 0.0; });
    });
  }
  EXPECT_EQ(callbacks.served, 10 * 8) << "the replays' callbacks came from the tape";
  EXPECT_EQ(requests, 20) << "a run of one and its replay, for each call";
}

TEST(BoundaryRuns, AReplayWhoseCallbacksDifferFailsTheCall) {
  // The same answer and state, but the callbacks' arguments depend on a count
  // kept between calls: not a function of the arguments and the generator.
  Callbacks callbacks;
  GeneratorCalls runs(Call::RaytracePixel, "PathTracer::raytrace_pixel", true, 1);
  Writer args;
  args.put(4);
  Rng rng(4);
  int calls = 0;
  try {
    runs.next(args, rng, [&](Call, const Writer& w) {
      ++calls;
      return pixel_run(w, callbacks, [&] { return calls == 1 ? 0.0 : 1e-9; });
    });
    FAIL() << "a replay that made other callbacks passed";
  } catch (const GeneratorContractBroken& e) {
    EXPECT_NE(std::string(e.what()).find("PathTracer::raytrace_pixel: its answer is not a function of its arguments"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace pt::boundary
