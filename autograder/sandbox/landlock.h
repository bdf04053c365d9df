#pragma once
// Landlock (Linux 5.13+, unprivileged): confine a process and its future
// children to a list of paths, so that the code under test can read the
// system's libraries and the paths it is given, write only its private
// working directory, execute only its own binary and the dynamic loader, and
// (ABI 4+) use no TCP, (ABI 6+) signal no process outside the sandbox.
#include <string>
#include <vector>

namespace pt::grade {

// The Landlock ABI this kernel offers, 0 when none.
int landlock_abi();

struct LandlockRules {
  std::vector<std::string> read;     // folders and files, read-only
  std::vector<std::string> write;    // folders, read and write
  std::vector<std::string> execute;  // files that may be executed (and read)
  std::vector<std::string> devices;  // files read and written: /dev/null
};

// Builds a ruleset handling every access right `abi` knows, of which only the
// rules' are granted; paths that do not exist are skipped. It has no effect
// yet: the paths are opened now, by whoever may (before giving up root).
// Returns its descriptor, or -1 with *error saying what failed.
int landlock_ruleset(const LandlockRules& rules, int abi, std::string* error);

// Restricts the calling thread, and what it executes, to the ruleset.
// Requires no_new_privs. Returns "" or what failed.
std::string landlock_enforce(int ruleset);

// The dynamic loader an ELF executable names (PT_INTERP), "" when none.
std::string elf_interpreter(const std::string& binary);

}  // namespace pt::grade
