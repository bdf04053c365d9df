#pragma once
// Keeping the solution's text out of what a student is shown. The manifest
// carries a fingerprint of every telling line of the solution files
// (reference/*.cpp, the hidden tests); a failure message or output line of a
// graded test that matches one (whitespace aside) is replaced before it
// reaches a report. Landlock already keeps those files out of the code under
// test's reach; this stops the plain copy where Landlock is missing (or the
// files are readable some other way). A submission that encodes the text
// (base64, reversed, one word per test) is not stopped by it: that takes
// deliberate code, in the task file an instructor can read.
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace pt::grade {

// Fingerprints of a file's telling lines: at least 16 characters once
// whitespace is removed, and not an #include.
std::vector<uint64_t> line_fingerprints(const std::string& path);

class Redactor {
 public:
  Redactor() = default;
  explicit Redactor(std::set<uint64_t> fingerprints) : fingerprints_(std::move(fingerprints)) {}
  // Replaces each line of `text` that matches; returns how many it replaced.
  size_t redact(std::string& text) const;

 private:
  std::set<uint64_t> fingerprints_;
};

}  // namespace pt::grade
