// The statistical tests' way of calling a task that draws (support/
// replayed_draws.h), in one process, against stand-ins for a student's task:
// a function of its arguments and generator passes every call; one that
// draws from elsewhere, averages a cache of earlier answers or hands back a
// generator moved back fails within the calls of any statistical test, with
// the message that says which.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <pcg_random.hpp>
#include <string>
#include <vector>

#include "core/rng.h"
#include "core/vec.h"
#include "support/replayed_draws.h"

namespace pt {
namespace {

// A stand-in for an estimator: how many numbers it draws depends on them.
Spectrum honest(Rng& rng) {
  double v = rng.uniform();
  if (v < 0.5) v += rng.uniform();
  return Spectrum(v);
}

// Calls `task` `calls` times as a test loop does; the message of the contract
// broken, or "" if none was.
template <class Task>
std::string loop(Task&& task, int calls = 2000) {
  Rng rng(21);
  try {
    for (int i = 0; i < calls; ++i) test::replayed("the task", rng, task);
  } catch (const GeneratorContractBroken& e) {
    return e.what();
  }
  return "";
}

const char* const kNotAFunction =
    "the task: its answer is not a function of its arguments and the generator passed in (randomness from "
    "somewhere else: a static generator, std::rand, state kept between calls)";

TEST(ReplayedDraws, AFunctionOfItsGeneratorPasses) {
  EXPECT_EQ(loop(honest, 100000), "");
  EXPECT_EQ(loop([](Rng&) { return Spectrum(0.5); }), "") << "drawing nothing is moving forward by zero";
}

TEST(ReplayedDraws, TheAnswersAreThoseOfOneCallAtATime) {
  Rng a(5), b(5);
  for (int i = 0; i < 1000; ++i) {
    ASSERT_EQ(test::replayed("the task", a, honest), honest(b));
    ASSERT_EQ(a.uniform(), b.uniform()) << "the generator after call " << i;
  }
}

TEST(ReplayedDraws, AStaticGeneratorFails) {
  // 2000 calls replay about 125: the chance that none is replayed is (15/16)^2000.
  EXPECT_NE(loop([](Rng&) {
              static Rng own(1);
              return Spectrum(own.uniform());
            }).find(kNotAFunction),
            std::string::npos);
}

TEST(ReplayedDraws, StdRandFails) {
  EXPECT_NE(loop([](Rng& rng) { return honest(rng) + Spectrum(std::rand() * 1e-12); }).find(kNotAFunction),
            std::string::npos);
}

TEST(ReplayedDraws, AnAverageOfEarlierAnswersFails) {
  // One sample a call, answered as the mean of the last 8: the variance of a
  // mean of 8 from one sample's work.
  std::vector<Spectrum> last;
  EXPECT_NE(loop([&last](Rng& rng) {
              last.push_back(honest(rng));
              if (last.size() > 8) last.erase(last.begin());
              Spectrum sum(0.0);
              for (const Spectrum& x : last) sum += x;
              return sum / double(last.size());
            }).find(kNotAFunction),
            std::string::npos);
}

TEST(ReplayedDraws, AGeneratorMovedBackOrReplacedFails) {
  // Handed back one draw behind the state it was given (a test that drew its
  // input from that generator would draw the same input again).
  const std::string back = loop([](Rng& rng) {
    const Rng given = rng;
    const Spectrum L = honest(rng);
    pcg32 engine;
    std::memcpy(static_cast<void*>(&engine), &rng, sizeof engine);
    engine.backstep(*draws_between(given, rng) + 1);
    std::memcpy(static_cast<void*>(&rng), &engine, sizeof engine);
    return L;
  });
  EXPECT_NE(back.find("the task handed back a generator that is not the one passed in moved forward: it was "
                      "moved backwards or replaced"),
            std::string::npos)
      << back;
  EXPECT_NE(loop([](Rng& rng) {
              const Spectrum L = honest(rng);
              rng = Rng(99, 3);  // another stream
              return L;
            }).find("moved backwards or replaced"),
            std::string::npos);
}

}  // namespace
}  // namespace pt
