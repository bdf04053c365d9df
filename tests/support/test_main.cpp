// Main of every test binary. Beyond GoogleTest's own flags it understands
//   --pt_list_graded   print the graded tests (JSON lines) and exit: how the
//                      grader's own build writes its manifest, from binaries
//                      that hold no student code
//   --pt_channel=V,S   report to pt-grade: one record when each test starts
//                      and one when it ends, written to descriptor V, each
//                      bound to the key read from descriptor S
//   --pt_seed=N        seed offset for statistical tests (see seed.h)
//
// The key reaches this program on a pipe, never in argv or the environment
// (which a static initializer can read), and is taken from .preinit_array:
// the dynamic loader runs those entries before every static initializer, and
// this file is linked first, so no code of a task file runs while the key is
// still in its descriptor. What that does and does not stop is in
// autograder/README.md.
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/graded.h"
#include "support/seed.h"

namespace {

// Constant-initialised (no constructor runs), internal linkage: nothing
// outside this file can name them.
int g_channel_fd = -1;
char g_channel_key[65];
constexpr size_t kKeyLength = 32;
constexpr size_t kMaxMessage = 16 * 1024;  // per record; a failing EXPECT in a loop can write megabytes

bool is_fifo(int fd) {
  struct stat st;
  return ::fstat(fd, &st) == 0 && S_ISFIFO(st.st_mode);
}

void take_channel(int argc, char** argv, char**) {
  for (int i = 1; i < argc; ++i) {
    int verdicts = -1, key = -1;
    char extra;
    if (std::sscanf(argv[i], "--pt_channel=%d,%d%c", &verdicts, &key, &extra) != 2) continue;
    size_t got = 0;
    while (is_fifo(key) && got < kKeyLength) {
      const ssize_t n = ::read(key, g_channel_key + got, kKeyLength - got);
      if (n > 0)
        got += static_cast<size_t>(n);
      else if (n == 0 || errno != EINTR)
        break;
    }
    ::close(key);
    g_channel_key[got] = '\0';
    if (got == kKeyLength && is_fifo(verdicts)) {
      g_channel_fd = verdicts;
      ::fcntl(verdicts, F_SETFD, FD_CLOEXEC);
    }
    return;
  }
}

__attribute__((section(".preinit_array"), used)) void (*const g_take_channel)(int, char**, char**) = take_channel;

void write_all(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n > 0)
      done += static_cast<size_t>(n);
    else if (n < 0 && errno != EINTR)
      return;  // the channel is gone: the grader will see no record, which fails the test
  }
}

void report(nlohmann::json record) {
  if (g_channel_fd < 0) return;
  record["k"] = g_channel_key;
  // A student message may hold invalid UTF-8: replace it rather than throw.
  write_all(g_channel_fd, record.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

// Threads already running when main() starts were started by a static
// initializer: nothing in the framework does that, so the grader notes it.
int running_threads() {
  DIR* dir = ::opendir("/proc/self/task");
  if (!dir) return -1;
  int n = 0;
  while (const dirent* e = ::readdir(dir)) n += e->d_name[0] != '.';
  ::closedir(dir);
  return n;
}

nlohmann::json describe(const pt::grading::GradedTest& t) {
  return {{"test", t.full_name()},
          {"task", t.task},
          {"points", t.points},
          {"visibility", t.visibility == pt::grading::Visibility::Visible ? "visible" : "hidden"}};
}

std::string failure_messages(const testing::TestResult& r) {
  std::string messages;
  for (int i = 0; i < r.total_part_count(); ++i) {
    const auto& part = r.GetTestPartResult(i);
    if (!part.failed()) continue;
    if (!messages.empty()) messages += "\n";
    if (part.file_name()) messages += std::string(part.file_name()) + ":" + std::to_string(part.line_number()) + ": ";
    messages += part.message();
    if (messages.size() > kMaxMessage) return messages.substr(0, kMaxMessage) + "\n... (truncated)";
  }
  return messages;
}

// Records the grading properties of each test (for --gtest_output) and reports
// its start and its end on the channel.
class GradingListener : public testing::EmptyTestEventListener {
 public:
  void OnTestStart(const testing::TestInfo& info) override {
    const std::string name = std::string(info.test_suite_name()) + "." + info.name();
    if (const auto* g = pt::grading::find(info.test_suite_name(), info.name())) {
      testing::Test::RecordProperty("task", g->task);
      testing::Test::RecordProperty("points", std::to_string(g->points));
      testing::Test::RecordProperty("visibility", g->visibility == pt::grading::Visible ? "visible" : "hidden");
    }
    report({{"start", name}});
  }

  void OnTestEnd(const testing::TestInfo& info) override {
    const testing::TestResult& r = *info.result();
    report({{"end", std::string(info.test_suite_name()) + "." + info.name()},
            {"passed", r.Passed()},
            {"skipped", r.Skipped()},
            {"seconds", r.elapsed_time() / 1000.0},
            {"message", failure_messages(r)}});
  }
};

}  // namespace

int main(int argc, char** argv) {
  const int threads = running_threads();
  testing::InitGoogleTest(&argc, argv);
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--pt_list_graded") == 0) {
      for (const auto& t : pt::grading::registry()) std::cout << describe(t).dump() << "\n";
      return 0;
    }
    if (std::strncmp(argv[i], "--pt_seed=", 10) == 0) pt::test::set_seed_offset(std::strtoull(argv[i] + 10, nullptr, 10));
  }
  report({{"hello", {{"threads", threads}}}});
  testing::UnitTest::GetInstance()->listeners().Append(new GradingListener);
  const int status = RUN_ALL_TESTS();
  report({{"done", status}});
  return status;
}
