#pragma once
// Running a trusted helper program (nm, readelf, pt-grade) and keeping its
// standard output. Not for code under test: that goes through sandbox.h.
#include <string>
#include <vector>

namespace pt::grade {

// Runs argv[0] (a path, or a name looked up in PATH) and appends its standard
// output to *output when given (else it goes to standard error); standard
// error passes through. With kill_after > 0 (and no output wanted) it is
// killed with SIGKILL after that many seconds. Returns its exit status,
// 128 + the signal when a signal ended it, or -1 when it could not start.
int run_command(const std::vector<std::string>& argv, std::string* output, double kill_after = 0);

}  // namespace pt::grade
