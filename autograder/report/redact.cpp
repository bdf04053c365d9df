#include "report/redact.h"

#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace pt::grade {
namespace {

// 64-bit FNV-1a of the line without whitespace: stable across builds, so the
// manifest's fingerprints stay valid for any pt-grade that reads them.
bool fingerprint(const std::string& line, uint64_t* out) {
  uint64_t h = 14695981039346656037ull;
  size_t chars = 0;
  for (unsigned char c : line) {
    if (std::isspace(c)) continue;
    h = (h ^ c) * 1099511628211ull;
    ++chars;
  }
  *out = h;
  const auto first = line.find_first_not_of(" \t");
  return chars >= 16 && (first == std::string::npos || line.compare(first, 8, "#include") != 0);
}

}  // namespace

std::vector<uint64_t> line_fingerprints(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::vector<uint64_t> out;
  for (std::string line; std::getline(in, line);)
    if (uint64_t h; fingerprint(line, &h)) out.push_back(h);
  return out;
}

size_t Redactor::redact(std::string& text) const {
  if (fingerprints_.empty() || text.empty()) return 0;
  std::istringstream in(text);
  std::string out;
  size_t replaced = 0, run = 0;  // a run of removed lines becomes one marker
  auto close_run = [&] {
    if (run > 0)
      out += "[pt-grade: " + std::to_string(run) + (run == 1 ? " line" : " lines") + " of the solution removed here]\n";
    run = 0;
  };
  for (std::string line; std::getline(in, line);) {
    uint64_t h;
    // A line may carry a prefix ("C++ exception with description \"..."):
    // try it whole, and from each point where the solution's line could start.
    bool hit = fingerprint(line, &h) && fingerprints_.count(h);
    for (size_t from = line.find_first_of("\"':"); !hit && from != std::string::npos;
         from = line.find_first_of("\"':", from + 1))
      hit = fingerprint(line.substr(from + 1), &h) && fingerprints_.count(h);
    replaced += hit;
    if (hit) {
      ++run;
      continue;
    }
    close_run();
    out += line + '\n';
  }
  close_run();
  if (!text.empty() && text.back() != '\n' && !out.empty()) out.pop_back();
  text = std::move(out);
  return replaced;
}

}  // namespace pt::grade
