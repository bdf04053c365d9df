#pragma once
// What the command-line tools share: exit statuses, and CLI11 checks that
// refuse NaN and infinities (CLI11's Range lets NaN through, since every
// comparison with it is false) and name the bound.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace pt {

// 0: success. 1: the work failed (a render stopped by a task's exception; an
// image worse than the threshold). 2: the input or the command line is
// unusable, or the output cannot be written: the message says what and where.
constexpr int kExitBadInput = 2;

// Parses the command line. Returns the exit status when the tool should stop
// at once: 0 after --help, kExitBadInput (with "error: ..." on stderr) for a
// bad command line.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << "\n(run with --help for the options)\n";
    return kExitBadInput;
  }
  return std::nullopt;
}

inline std::string format_bound(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// A finite number in [lo, hi]; `why`, when given, says where the bound comes from.
inline CLI::Validator within(double lo, double hi, const std::string& why = "") {
  const std::string range = "[" + format_bound(lo) + ", " + format_bound(hi) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        char* end = nullptr;
        double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str()) return "";  // not a number: the conversion says so
        if (std::isfinite(v) && v >= lo && v <= hi) return "";
        return text + " is not in " + range + (why.empty() ? "" : " (" + why + ")");
      },
      "in " + range);
}

// An integer written without a sign (CLI11 reads "-1" into an unsigned as 2^64 - 1).
inline CLI::Validator unsigned_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (!text.empty() && text.find_first_not_of("0123456789") == std::string::npos) return "";
        return text + " is not a non-negative integer";
      },
      "");
}

}  // namespace pt
