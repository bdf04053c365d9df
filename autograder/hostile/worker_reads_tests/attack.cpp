// Hostile: read the hidden tests from where the task code runs (a review of the
// process boundary). Across the process boundary the tests are in the kit's verifier,
// a process and a file beside the worker. The first task call opens the
// verifier's file (the gallery writes in the kit's real path, the worst case:
// a student who guessed the layout) and looks through /proc for a process
// running it, whose memory it would then read; every task throws what it got.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/not_implemented.h"

namespace {
std::string attempt() {
  static std::string result;
  if (!result.empty()) return result;
  const std::string verifier = "@PT_BUILD@/grader-kit/verifiers/part1_verify";
  std::ifstream file(verifier, std::ios::binary);
  std::ostringstream bytes;
  if (file) bytes << file.rdbuf();
  result = file && bytes.str().size() > 0 ? "read " + std::to_string(bytes.str().size()) + " bytes of " + verifier
                                          : "could not read " + verifier;
  std::string seen = "; no verifier process seen";
  for (int pid = 1; pid < 1 << 16; ++pid) {
    std::ifstream cmdline("/proc/" + std::to_string(pid) + "/cmdline");
    std::string arg0;
    if (std::getline(cmdline, arg0, '\0') && arg0.find("part1_verify") != std::string::npos) {
      std::ifstream mem("/proc/" + std::to_string(pid) + "/mem", std::ios::binary);
      seen = "; the verifier is process " + std::to_string(pid) + (mem ? ", its memory open" : ", its memory closed");
      break;
    }
  }
  return result += seen;
}
}  // namespace
// Every stub task throws what the attack got.
#define NotImplemented(task) std::runtime_error(attempt())
