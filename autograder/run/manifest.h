#pragma once
// The trusted list of graded tests: per part, each test's name, task, points
// and visibility. The grader's own build writes it from the all-reference test
// binaries (which hold no student code) with `pt-grade manifest`; pt-grade
// reads it once, before any code under test runs. Nothing a binary under test
// prints or reports can add a test, drop one or change its points.
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace pt::grade {

struct ManifestTest {
  std::string name;  // GoogleTest's Suite.Name
  std::string task;  // P1T3
  double points = 0;
  bool hidden = false;
  bool extension = false;  // an optional task's test (P5T3): 0 points unless counted
  bool uncounted() const { return extension && points == 0; }  // an extension left at 0 points
};

using PartManifest = std::vector<ManifestTest>;

struct Manifest {
  std::map<int, PartManifest> parts;
  std::set<uint64_t> solution_lines;  // fingerprints of the solution's lines (redact.h)
};

// Parses what `BINARY --pt_list_graded` prints (one JSON object per line) as
// the tests of `part`; throws std::runtime_error naming the offending line.
PartManifest parse_listing(int part, const std::string& text);

// Reads a manifest file; throws std::runtime_error naming the file and the fault.
Manifest read_manifest(const std::string& path);

// Extension tests keep their points only when the instructor counts them
// (`--count-extensions`); otherwise they are graded and reported at 0 points.
// Returns how many tests it set to 0.
int leave_extensions_uncounted(Manifest& manifest);

// Writes it atomically (temporary file, then rename). `sources` names the
// binary each part was listed from.
void write_manifest(const std::string& path, const Manifest& manifest, const std::map<int, std::string>& sources);

}  // namespace pt::grade
