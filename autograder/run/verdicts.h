#pragma once
// The grader's end of the verdict channel. The test main
// (tests/support/test_main.cpp) writes one JSON line when a test starts and
// one when it ends, each carrying the run's key, on a pipe it inherits; the key
// reaches it on a second pipe that it empties before any static initializer
// runs. Lines without the key are counted and ignored: they can only come from
// code under test.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pt::grade {

// A fresh key per run: 32 hex digits from the kernel's random source.
std::string make_key();

// argv flag that tells the test main where the channel is (descriptors 3 and 4).
inline constexpr int kVerdictFd = 3, kKeyFd = 4;
inline constexpr const char* kChannelFlag = "--pt_channel=3,4";

struct Verdict {
  std::string test;
  bool passed = false, skipped = false;
  double seconds = 0;
  std::string message;  // GoogleTest's failure text
};

class VerdictStream {
 public:
  explicit VerdictStream(std::string key) : key_(std::move(key)) {}

  // Takes raw bytes from the pipe; returns how many keyed records they completed.
  size_t feed(std::string_view bytes);

  bool hello() const { return hello_; }            // the test main started
  int threads_at_main() const { return threads_; }  // threads running when it did (1 when none was started early)
  bool done() const { return done_; }              // RUN_ALL_TESTS returned
  const std::string& running() const { return running_; }  // started, not ended ("" when none)
  const std::vector<Verdict>& verdicts() const { return verdicts_; }
  size_t ignored() const { return ignored_; }  // lines without this run's key, or malformed

 private:
  bool take(const std::string& line);  // true for a keyed record

  std::string key_, partial_, running_;
  bool hello_ = false, done_ = false, overlong_ = false;
  int threads_ = 0;
  std::vector<Verdict> verdicts_;
  size_t ignored_ = 0;
};

}  // namespace pt::grade
