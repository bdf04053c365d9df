// Runs of one call across the boundary (boundary/repeated_call.h): the answers
// a test receives from a run are those it would have received one call at a
// time, a run is only used while the test repeats the same call from the state
// the last answer left, and a worker that answers more than it was asked
// breaks the link.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "repeated_call.h"

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
    answer_run<double>(in, run, [&](Rng& rng) {
      if (throw_from && std::memcmp(&rng, throw_from, sizeof(Rng)) == 0) throw std::runtime_error("the student's function threw");
      return estimator(arg, rng);
    });
    in.finish();
    if (extra == 0) return run.bytes();
    // A hostile worker: says it sends more answers than were asked for, and does.
    Reader r(run.bytes());
    Writer out;
    out.put(r.get<uint32_t>() + extra).put_bytes(run.bytes().substr(sizeof(uint32_t)));
    for (uint32_t i = 0; i < extra; ++i) out.put(0.0).put(Rng());
    return out.bytes();
  }
};

Writer args_of(double arg) {
  Writer w;
  w.put(arg);
  return w;
}

TEST(BoundaryRuns, AnswersAreThoseOfOneCallAtATime) {
  FakeWorker worker;
  RepeatedCall<double> runs(Call::DirectImportance);
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
  RepeatedCall<double> runs(Call::DirectImportance);
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
  RepeatedCall<double> runs(Call::DirectImportance);
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
  RepeatedCall<double> runs(Call::DirectImportance);
  Rng rng(5);
  EXPECT_THROW(runs.next(args_of(0.5), rng, [&](Call c, const Writer& w) { return worker(c, w); }), LinkBroken);
}

TEST(BoundaryRuns, AWorkerThatAnswersNothingBreaksTheLink) {
  RepeatedCall<double> runs(Call::DirectImportance);
  Rng rng(5);
  Writer nothing;
  nothing.put(uint32_t{0});
  EXPECT_THROW(runs.next(args_of(0.5), rng, [&](Call, const Writer&) { return nothing.bytes(); }), LinkBroken);
}

}  // namespace
}  // namespace pt::boundary
