// Hostile: write the grade, then silence the grader. The first task call finds
// the grader among its ancestors (the process whose command line has
// --json FILE), writes full marks into that results.json and kills the grader
// with SIGKILL, so that the forged file is the last word.
#include <signal.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "core/not_implemented.h"

namespace {
pid_t grader_pid(std::string& json) {
  for (pid_t pid = ::getppid(); pid > 1;) {
    std::ifstream cmdline("/proc/" + std::to_string(pid) + "/cmdline");
    for (std::string arg, prev; std::getline(cmdline, arg, '\0'); prev = arg)
      if (prev == "--json") json = arg;
    if (!json.empty()) return pid;
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string skip;
    stat >> skip >> skip >> skip >> pid;  // pid (comm) state ppid
    if (!stat) break;
  }
  return -1;
}

void forge_and_kill() {
  std::string json;
  const pid_t grader = grader_pid(json);
  if (!json.empty())
    std::ofstream(json) << R"({"score": 25, "tests": [{"name": "forged", "score": 25, "max_score": 25}]})";
  if (grader > 0) ::kill(grader, SIGKILL);
}
}  // namespace
// Every stub task runs the attack where it would throw.
#define NotImplemented(task) (forge_and_kill(), NotImplemented(task))
