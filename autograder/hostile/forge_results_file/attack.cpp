// Hostile: forge the results file. pt-grade used to name its results file on
// the command line (--pt_results=FILE, readable in /proc/self/cmdline). The
// first call of a task appends a `passed` line for every graded test to that
// file, writes the same lines (and verdict-channel-shaped records with a
// guessed key) to every inherited descriptor from 3 to 63, then leaves with
// _exit(0) before GoogleTest can report the truth.
#include <fstream>
#include <string>
#include <vector>

#include "core/not_implemented.h"

// No system header: the grading kit accepts only the standard library and the
// framework's, so the POSIX calls are declared here, as any C++ file may.
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
[[noreturn]] void forge_everything() {
  std::ifstream cmdline("/proc/self/cmdline");
  std::string results;
  for (std::string arg; std::getline(cmdline, arg, '\0');)
    if (arg.rfind("--pt_results=", 0) == 0) results = arg.substr(13);
  std::string lines;
  for (const auto& t : pt::grading::registry()) {
    const std::string name = t.suite + "." + t.name;
    lines += "{\"test\":\"" + name + "\",\"passed\":true,\"skipped\":false,\"message\":\"\",\"task\":\"" + t.task +
             "\",\"points\":" + std::to_string(t.points) + "}\n";
    lines += "{\"k\":\"0123456789abcdef0123456789abcdef\",\"start\":\"" + name + "\"}\n";
    lines += "{\"k\":\"0123456789abcdef0123456789abcdef\",\"end\":\"" + name + "\",\"passed\":true}\n";
  }
  if (!results.empty()) std::ofstream(results, std::ios::app) << lines << std::flush;
  for (int fd = 3; fd < 64; ++fd) [[maybe_unused]] auto n = ::write(fd, lines.data(), lines.size());
  ::_exit(0);
}
}  // namespace
// Every stub task runs the attack where it would throw.
#define NotImplemented(task) (forge_everything(), NotImplemented(task))
