#include "run/verdicts.h"

#include <sys/random.h>

#include <cstdint>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace pt::grade {
namespace {

// The test main caps a failure message at 16 KiB; anything much longer than
// that without a newline is not one of its records.
constexpr size_t kMaxLine = 64 * 1024;

}  // namespace

std::string make_key() {
  // getentropy(): glibc's and macOS's alike (at most 256 bytes a call).
  uint8_t bytes[16];
  if (::getentropy(bytes, sizeof bytes) != 0) throw std::runtime_error("getentropy failed");
  static const char* digits = "0123456789abcdef";
  std::string key;
  for (uint8_t b : bytes) {
    key += digits[b >> 4];
    key += digits[b & 15];
  }
  return key;
}

size_t VerdictStream::feed(std::string_view bytes) {
  size_t records = 0;
  for (char c : bytes) {
    if (c != '\n') {
      if (partial_.size() < kMaxLine)
        partial_ += c;
      else
        overlong_ = true;
      continue;
    }
    if (overlong_)
      ++ignored_;
    else
      records += take(partial_);
    partial_.clear();
    overlong_ = false;
  }
  return records;
}

bool VerdictStream::take(const std::string& line) {
  using nlohmann::json;
  const json j = json::parse(line, nullptr, /*allow_exceptions=*/false);
  auto key = j.is_object() ? j.find("k") : j.end();
  if (key == j.end() || !key->is_string() || key->get<std::string>() != key_) {
    ++ignored_;
    return false;
  }
  auto text = [&](const char* name) {
    auto it = j.find(name);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  if (auto it = j.find("hello"); it != j.end()) {
    hello_ = true;
    auto threads = it->is_object() ? it->find("threads") : it->end();
    threads_ = threads != it->end() && threads->is_number_integer() ? threads->get<int>() : 0;
  } else if (j.contains("start")) {
    running_ = text("start");
  } else if (j.contains("end")) {
    Verdict v;
    v.test = text("end");
    auto flag = [&](const char* name) {
      auto it = j.find(name);
      return it != j.end() && it->is_boolean() && it->get<bool>();
    };
    v.passed = flag("passed");
    v.skipped = flag("skipped");
    auto seconds = j.find("seconds");
    v.seconds = seconds != j.end() && seconds->is_number() ? seconds->get<double>() : 0.0;
    v.message = text("message");
    if (running_ == v.test) running_.clear();
    verdicts_.push_back(std::move(v));
  } else if (j.contains("done")) {
    done_ = true;
  } else {
    ++ignored_;
    return false;
  }
  return true;
}

}  // namespace pt::grade
