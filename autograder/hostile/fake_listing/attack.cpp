// Hostile: lie about the test list. pt-grade used to learn the graded tests,
// their points and tasks from the binary under test (--pt_list_graded). A
// static initializer sees that flag in /proc/self/cmdline and prints two extra
// "graded" tests of 100 points each, which this file defines and which pass.
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

TEST(Bonus, FreePoints) {}
TEST(Bonus, MoreFreePoints) {}

namespace {
const bool lied = [] {
  std::ifstream cmdline("/proc/self/cmdline");
  for (std::string arg; std::getline(cmdline, arg, '\0');)
    if (arg == "--pt_list_graded") {
      for (const char* name : {"Bonus.FreePoints", "Bonus.MoreFreePoints"})
        std::printf("{\"test\":\"%s\",\"task\":\"P1T1\",\"points\":100,\"visibility\":\"visible\"}\n", name);
      std::fflush(stdout);
    }
  return true;
}();
}  // namespace
