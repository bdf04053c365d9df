// Main of every test binary. Beyond GoogleTest's own flags it understands
//   --pt_list_graded   print the graded tests (JSON lines) and exit: how the
//                      grader's own build writes its manifest, from binaries
//                      that hold no student code
//   --pt_channel=V,S   report to pt-grade: one record when each test starts
//                      and one when it ends, written to descriptor V, each
//                      bound to the key read from descriptor S
//   --pt_seed=N        seed offset for statistical tests (see seed.h)
//   --pt_image_dir=DIR where a failing image test writes its images
//                      (image_test_files.h): pt-grade's folder for its report
//   --pt_test_timeout=S  the time limit of one graded test (default 20 s, as
//                      pt-grade's; 0: none). A graded test still running
//                      then is named with its task and a short stack of the
//                      thread running it, and the binary exits with status
//                      124, so that a hang never waits forever. Under pt-grade
//                      (--pt_channel) the diagnosis comes a little before the
//                      limit and pt-grade, on its own clock, ends the run: the
//                      verdict stays the grader's.
//
// The key reaches this program on a pipe, never in argv or the environment,
// and is taken from .preinit_array, the first code the dynamic loader runs
// (this file is linked first). Under pt-grade every part is graded across
// the process boundary: this process holds no task's code, and the key is
// depth behind the sandbox against a worker that reaches this process's
// descriptors from outside (through /proc/PID/fd, where no PID namespace and
// no Landlock keep it away): the process makes itself undumpable at the same
// moment, which closes /proc/PID/fd and /proc/PID/mem to other processes of
// its user, and the key is gone from its pipe. In a binary with the task's
// code in it (pt-grade run --binary, a convenience) the key is only as safe
// as that code lets it be. The grader's threat model says more (the README of
// pt-grade, in instructors' copies).
#include <dirent.h>
#include <dlfcn.h>
#include <execinfo.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cxxabi.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#ifdef PT_UNDUMPABLE  // with the grader's sandbox (Linux's: tests/CMakeLists.txt); macOS has no prctl
#include <sys/prctl.h>
#endif

#include "support/graded.h"
#include "support/image_test_files.h"
#include "support/measure.h"
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
#ifdef PT_UNDUMPABLE
    ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
#endif
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

#ifdef __ELF__
__attribute__((section(".preinit_array"), used)) void (*const g_take_channel)(int, char**, char**) = take_channel;
#endif  // elsewhere (macOS) main() takes it: check-submission's runs there, unconfined

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

}  // namespace

void pt::grading::report_measure(const std::string& name, double value) {
  report({{"measure", name}, {"value", value}});
}

namespace {

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
  nlohmann::json j = {{"test", t.full_name()},
                      {"task", t.task},
                      {"points", t.points},
                      {"visibility", t.visibility == pt::grading::Visibility::Visible ? "visible" : "hidden"}};
  if (t.extension) j["extension"] = true;
  return j;
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

// The per-test time limit. The thread that runs the tests is asked for its
// stack with a signal (its handler only records the return addresses: no
// allocation, no locks); the watchdog thread names them.
constexpr int kStackSignal = SIGURG;  // ignored by default, used by nothing here
constexpr int kMaxFrames = 48;
void* g_frames[kMaxFrames];
std::atomic<int> g_frame_count{-1};

void record_stack(int) { g_frame_count.store(backtrace(g_frames, kMaxFrames)); }

std::string function_name(void* address) {
  Dl_info info{};
  if (!dladdr(address, &info)) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%p", address);
    return buf;
  }
  if (!info.dli_sname) {
    // The file's name, not its path: under a grader the path is the grading
    // kit's, which a report must not show.
    const char* slash = info.dli_fname ? std::strrchr(info.dli_fname, '/') : nullptr;
    const char* file = slash ? slash + 1 : info.dli_fname ? info.dli_fname : "?";
    char buf[160];
    const auto base = reinterpret_cast<uintptr_t>(info.dli_fbase);
    std::snprintf(buf, sizeof buf, "%s+0x%zx", file,
                  static_cast<size_t>(reinterpret_cast<uintptr_t>(address) - base - 1));
    return buf;
  }
  int status = 1;
  char* demangled = abi::__cxa_demangle(info.dli_sname, nullptr, nullptr, &status);
  std::string name = status == 0 && demangled ? demangled : info.dli_sname;
  std::free(demangled);
  return name.size() > 200 ? name.substr(0, 200) + "..." : name;
}

// Up to 8 frames of the test thread, innermost first, without the frames of
// the signal itself.
std::string short_stack(pthread_t thread) {
  g_frame_count.store(-1);
  if (pthread_kill(thread, kStackSignal) != 0) return "  (no stack: the signal could not be sent)\n";
  for (int i = 0; i < 100 && g_frame_count.load() < 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const int n = g_frame_count.load();
  if (n <= 0) return "  (no stack: the test thread did not answer)\n";
  std::string out;
  int shown = 0;
  for (int i = 2; i < n && shown < 8; ++i, ++shown) out += "  #" + std::to_string(shown) + " " + function_name(g_frames[i]) + "\n";
  out += "  (an address FILE+0x.. names a function: addr2line -f -C -e FILE 0x..)\n";
  return out;
}

class Watchdog {
 public:
  Watchdog(double limit_seconds, bool under_grader)
      : limit_(limit_seconds), under_grader_(under_grader), tests_thread_(pthread_self()) {
    struct sigaction sa {};
    sa.sa_handler = record_stack;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(kStackSignal, &sa, nullptr);
    void* warm[1];
    backtrace(warm, 1);  // loads the unwinder now, not in the signal handler
    thread_ = std::thread([this] { watch(); });
    thread_.detach();  // it never outlives a hang, and never stops an exit
  }

  void start(const std::string& name, const std::string& task) {
    std::lock_guard<std::mutex> lock(mutex_);
    name_ = name;
    task_ = task;
    ++generation_;
    started_ = std::chrono::steady_clock::now();
    running_ = true;
    wake_.notify_all();
  }
  void end() {
    std::lock_guard<std::mutex> lock(mutex_);
    running_ = false;
    ++generation_;
  }

 private:
  void watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return running_; });
      const long generation = generation_;
      // Under pt-grade: the diagnosis before pt-grade's own limit ends the run.
      const double at = under_grader_ ? limit_ - std::min(2.0, limit_ / 10) : limit_;
      const auto when = started_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                       std::chrono::duration<double>(at));
      if (wake_.wait_until(lock, when, [&] { return generation_ != generation; })) continue;
      const std::string name = name_, task = task_;
      lock.unlock();
      char head[400];
      std::snprintf(head, sizeof head, "[  TIMEOUT ] %s (%s) still running after %.0f s%s; the test thread is in:\n",
                    name.c_str(), task.c_str(), at, under_grader_ ? "" : " (the limit per test): stopped");
      const std::string text = head + short_stack(tests_thread_);
      std::fflush(stdout);
      write_all(STDERR_FILENO, text);
      if (!under_grader_) std::_Exit(124);
      lock.lock();
      wake_.wait(lock, [&] { return generation_ != generation; });  // the grader ends the run
    }
  }

  const double limit_;
  const bool under_grader_;
  const pthread_t tests_thread_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::string name_, task_;
  long generation_ = 0;
  bool running_ = false;
  std::chrono::steady_clock::time_point started_;
};

Watchdog* g_watchdog = nullptr;  // graded tests only: the framework's and library's own tests run as long as they need

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
      if (g->extension) testing::Test::RecordProperty("extension", "true");
      if (g_watchdog) g_watchdog->start(name, g->task);
    }
    report({{"start", name}});
  }

  void OnTestEnd(const testing::TestInfo& info) override {
    if (g_watchdog) g_watchdog->end();
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
#ifndef __ELF__
  take_channel(argc, argv, nullptr);
#endif
  const int threads = running_threads();
  testing::InitGoogleTest(&argc, argv);
  double test_timeout = 20;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--pt_list_graded") == 0) {
      for (const auto& t : pt::grading::registry()) std::cout << describe(t).dump() << "\n";
      return 0;
    }
    if (std::strncmp(argv[i], "--pt_seed=", 10) == 0) pt::test::set_seed_offset(std::strtoull(argv[i] + 10, nullptr, 10));
    if (std::strncmp(argv[i], "--pt_test_timeout=", 18) == 0) test_timeout = std::strtod(argv[i] + 18, nullptr);
    if (std::strncmp(argv[i], "--pt_image_dir=", 15) == 0) pt::image_test::set_failure_image_dir(argv[i] + 15);
  }
  if (test_timeout > 0 && !pt::grading::registry().empty()) g_watchdog = new Watchdog(test_timeout, g_channel_fd >= 0);
#ifdef PT_NO_PREBUILT_FOR
  std::fprintf(stderr, "note: this release has no prebuilt solution for " PT_NO_PREBUILT_FOR
                       ": every part in this binary is your own code (tasks/), the part under test and the others "
                       "alike, so an unfinished part fails here too (prebuilt/README.md)\n");
#endif
  report({{"hello", {{"threads", threads}}}});
  testing::UnitTest::GetInstance()->listeners().Append(new GradingListener);
  const int status = RUN_ALL_TESTS();
  report({{"done", status}});
  return status;
}
