// A worker's outcome, handed back by the grader's helper as JSON
// (run_outcome.h): what it says crosses unchanged, and anything else, from a
// truncated write to bytes forged in front of the real object, reads as a
// lost run, never as another outcome.
#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <csignal>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "run/run_outcome.h"

namespace pt::grade {
namespace {

RunOutcome crashed_worker() {
  RunOutcome r;
  r.exit.how = Exit::How::Signaled;
  r.exit.code = 11;
  r.exit.seconds = 0.25;
  r.exit.limit = 20;
  r.exit.error = "";
  r.output = std::string("line one\n\"quoted\" \\ tab\t") + '\0' + "after a NUL\nüñí\n";
  r.output_bytes = 1ull << 40;
  return r;
}

void expect_same(const RunOutcome& a, const RunOutcome& b) {
  EXPECT_EQ(a.exit.how, b.exit.how);
  EXPECT_EQ(a.exit.code, b.exit.code);
  EXPECT_EQ(a.exit.seconds, b.exit.seconds);
  EXPECT_EQ(a.exit.limit, b.exit.limit);
  EXPECT_EQ(a.exit.error, b.exit.error);
  EXPECT_EQ(a.output, b.output);
  EXPECT_EQ(a.output_bytes, b.output_bytes);
}

void expect_lost(const std::string& text) {
  const RunOutcome r = parse_outcome(text);
  EXPECT_EQ(r.exit.how, Exit::How::Lost) << text.substr(0, 200);
  EXPECT_NE(r.exit.error.find("without saying how the worker ended"), std::string::npos) << r.exit.error;
  EXPECT_TRUE(r.output.empty());
}

TEST(RunOutcome, CrossesUnchanged) {
  const RunOutcome sent = crashed_worker();
  expect_same(parse_outcome(outcome_json(sent)), sent);
  for (Exit::How how : {Exit::How::Exited, Exit::How::TimedOut, Exit::How::NotStarted, Exit::How::Lost}) {
    RunOutcome r = sent;
    r.exit.how = how;
    r.exit.error = "why it did not start";
    expect_same(parse_outcome(outcome_json(r)), r);
  }
}

TEST(RunOutcome, InvalidUtf8InTheOutputBecomesReplacementCharacters) {
  RunOutcome sent = crashed_worker();
  sent.output = "a\xff" "b";
  EXPECT_EQ(parse_outcome(outcome_json(sent)).output, "a\xEF\xBF\xBD" "b");
}

TEST(RunOutcome, MalformedReadsAsLost) {
  const std::string real = outcome_json(crashed_worker());
  expect_lost("");
  expect_lost("{");
  expect_lost(real.substr(0, real.size() / 2));  // the helper died mid-write
  expect_lost("[" + real + "]");
  expect_lost("2 11 0.25 20 0 0 0 ");  // the hand-written protocol this replaced
  expect_lost(std::string(1 << 17, '['));  // nested past any sense, without a crash
}

TEST(RunOutcome, EachFieldMustBeThereWithItsType) {
  const nlohmann::json real = nlohmann::json::parse(outcome_json(crashed_worker()));
  for (const auto& [key, value] : real.items()) {
    nlohmann::json missing = real;
    missing.erase(key);
    expect_lost(missing.dump());
    nlohmann::json retyped = real;
    retyped[key] = nlohmann::json::array();
    expect_lost(retyped.dump());
  }
  nlohmann::json extra = real;
  extra["passed"] = true;
  expect_lost(extra.dump());
  for (const nlohmann::json& how : {nlohmann::json("passed"), nlohmann::json(0)}) {
    nlohmann::json bad = real;
    bad["how"] = how;
    expect_lost(bad.dump());
  }
  for (const nlohmann::json& code : {nlohmann::json(1.5), nlohmann::json(1ull << 40), nlohmann::json(-(1ll << 40))}) {
    nlohmann::json bad = real;
    bad["code"] = code;
    expect_lost(bad.dump());
  }
  nlohmann::json negative = real;
  negative["seconds"] = -1;
  expect_lost(negative.dump());
  negative = real;
  negative["output_bytes"] = -1;
  expect_lost(negative.dump());
}

// A worker that reached the pipe (the helper's /proc/PID/fd, where nothing
// else stops it) can only write before the helper: its forged outcome in
// front of the real one must not be read as the outcome.
TEST(RunOutcome, AForgedOutcomeInFrontOfTheRealOneIsNotBelieved) {
  RunOutcome forged;
  forged.exit.how = Exit::How::Exited;
  forged.exit.code = 0;
  forged.output = "all is well";
  const std::string real = outcome_json(crashed_worker());
  expect_lost(outcome_json(forged) + real);
  expect_lost(outcome_json(forged) + "\n" + real);
  expect_lost("{\"how\": \"exited\", \"code\": 0, \"seconds\": 0, \"limit\": 0, \"error\": \"\", "
              "\"output_bytes\": 0, \"output\": " + real);
}

TEST(RunOutcome, MoreThanTheBoundFromThePipeReadsAsLost) {
  std::signal(SIGPIPE, SIG_IGN);  // the writer, cut off, fails instead of ending the test
  int fds[2];
  ASSERT_EQ(::pipe2(fds, O_CLOEXEC), 0);
  RunOutcome big = crashed_worker();
  big.output = std::string(300000, 'x');
  const std::string text = outcome_json(big);
  std::thread writer([&] {
    write_outcome(fds[1], big);
    ::close(fds[1]);
  });
  const RunOutcome r = read_outcome(fds[0], text.size() - 1);
  ::close(fds[0]);
  writer.join();
  EXPECT_EQ(r.exit.how, Exit::How::Lost);
  EXPECT_NE(r.exit.error.find("more than"), std::string::npos) << r.exit.error;

  ASSERT_EQ(::pipe2(fds, O_CLOEXEC), 0);
  std::thread exact([&] {
    write_outcome(fds[1], big);
    ::close(fds[1]);
  });
  const RunOutcome whole = read_outcome(fds[0], text.size());
  ::close(fds[0]);
  exact.join();
  expect_same(whole, big);
}

}  // namespace
}  // namespace pt::grade
