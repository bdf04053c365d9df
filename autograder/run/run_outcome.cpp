#include "run/run_outcome.h"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <limits>
#include <utility>

#include <nlohmann/json.hpp>

namespace pt::grade {
namespace {

using json = nlohmann::json;

constexpr std::array<std::pair<Exit::How, const char*>, 5> kHows{{{Exit::How::Exited, "exited"},
                                                                  {Exit::How::Signaled, "signaled"},
                                                                  {Exit::How::TimedOut, "timed-out"},
                                                                  {Exit::How::NotStarted, "not-started"},
                                                                  {Exit::How::Lost, "lost"}}};

RunOutcome lost(const std::string& why) {
  RunOutcome r;
  r.exit.how = Exit::How::Lost;
  r.exit.error = "the grader's helper that ran the worker ended without saying how the worker ended (" + why + ")";
  return r;
}

bool is_seconds(const json& j) { return j.is_number() && std::isfinite(j.get<double>()) && j.get<double>() >= 0; }

}  // namespace

std::string outcome_json(const RunOutcome& r) {
  const char* how = "lost";
  for (const auto& [value, name] : kHows)
    if (value == r.exit.how) how = name;
  const json j{{"how", how},         {"code", r.exit.code},   {"seconds", r.exit.seconds},
               {"limit", r.exit.limit}, {"error", r.exit.error}, {"output", r.output},
               {"output_bytes", r.output_bytes}};
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

RunOutcome parse_outcome(std::string_view text) {
  if (text.size() > kMaxOutcomeBytes) return lost("more than " + std::to_string(kMaxOutcomeBytes) + " bytes");
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return lost("not one JSON object");
  if (j.size() != 7) return lost("not exactly its seven fields");
  const auto field = [&j](const char* key) { return j.contains(key) ? j.at(key) : json(); };
  const json how = field("how"), code = field("code"), seconds = field("seconds"), limit = field("limit"),
             error = field("error"), output = field("output"), bytes = field("output_bytes");
  RunOutcome r;
  bool named = false;
  for (const auto& [value, name] : kHows)
    if (how == name) r.exit.how = value, named = true;
  if (!named) return lost("no known \"how\"");
  constexpr int64_t kMin = std::numeric_limits<int>::min(), kMax = std::numeric_limits<int>::max();
  const bool is_int = code.is_number_unsigned() ? code.get<uint64_t>() <= uint64_t(kMax)
                                                : code.is_number_integer() && code.get<int64_t>() >= kMin;
  if (!is_int) return lost("\"code\" is no int");
  if (!is_seconds(seconds) || !is_seconds(limit)) return lost("\"seconds\" or \"limit\" is no time");
  if (!error.is_string() || !output.is_string()) return lost("\"error\" or \"output\" is no string");
  if (!bytes.is_number_unsigned()) return lost("\"output_bytes\" is no count");
  r.exit.code = static_cast<int>(code.get<int64_t>());
  r.exit.seconds = seconds.get<double>();
  r.exit.limit = limit.get<double>();
  r.exit.error = error.get<std::string>();
  r.output = output.get<std::string>();
  r.output_bytes = bytes.get<uint64_t>();
  return r;
}

void write_outcome(int fd, const RunOutcome& r) {
  const std::string bytes = outcome_json(r);
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0 && errno != EINTR) return;
    if (n > 0) done += static_cast<size_t>(n);
  }
}

RunOutcome read_outcome(int fd, size_t max_bytes) {
  std::string bytes;
  char chunk[1 << 16];
  for (ssize_t n; (n = ::read(fd, chunk, sizeof chunk)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    bytes.append(chunk, static_cast<size_t>(n));
    if (bytes.size() > max_bytes) return lost("more than " + std::to_string(max_bytes) + " bytes");
  }
  return parse_outcome(bytes);
}

}  // namespace pt::grade
