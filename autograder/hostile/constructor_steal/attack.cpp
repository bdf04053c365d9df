// Hostile: a static initializer that looks for the channel's key. The
// earliest constructor a file can ask for (priority 101) reads every
// inherited descriptor; the first task call reports every graded test passed
// with whatever it found, then leaves before GoogleTest can report the truth.
#include <cstring>
#include <string>
#include <vector>

#include "core/not_implemented.h"

// No system header (the grading kit accepts none): the POSIX calls declared here.
extern "C" long read(int fd, void* data, unsigned long size);
extern "C" long write(int fd, const void* data, unsigned long size);
extern "C" [[noreturn]] void _exit(int status);

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
char g_key[64];

__attribute__((constructor(101))) void look_for_the_key() {
  for (int fd = 3; fd < 64 && g_key[0] == '\0'; ++fd)
    if (::read(fd, g_key, 32) != 32) g_key[0] = '\0';
}

[[noreturn]] void report_all_passed() {
  std::string lines;
  for (const auto& t : pt::grading::registry()) {
    const std::string name = t.suite + "." + t.name, key(g_key, std::strlen(g_key));
    lines += "{\"k\":\"" + key + "\",\"start\":\"" + name + "\"}\n";
    lines += "{\"k\":\"" + key + "\",\"end\":\"" + name + "\",\"passed\":true}\n";
  }
  [[maybe_unused]] auto n = ::write(3, lines.data(), lines.size());
  ::_exit(0);
}
}  // namespace
// Every stub task reports instead of throwing.
#define NotImplemented(task) (report_all_passed(), NotImplemented(task))
