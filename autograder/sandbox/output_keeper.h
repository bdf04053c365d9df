#pragma once
// The head and the tail of a run's output (sandbox.h), for both sandboxes.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

namespace pt::grade {

// The head and the tail of whatever the run prints: a flood costs the grader
// CPU time (bounded by the time limits), never disk or memory.
class OutputKeeper {
 public:
  OutputKeeper(size_t head, size_t tail) : head_max_(head), tail_max_(tail) {}
  void add(const char* data, size_t n) {
    total_ += n;
    const size_t to_head = std::min(n, head_max_ - head_.size());
    head_.append(data, to_head);
    data += to_head;
    n -= to_head;
    if (n == 0) return;
    tail_.append(data, n);
    if (tail_.size() > 2 * tail_max_) tail_.erase(0, tail_.size() - tail_max_);
  }
  uint64_t total() const { return total_; }
  std::string text() const {
    const std::string tail = tail_.size() > tail_max_ ? tail_.substr(tail_.size() - tail_max_) : tail_;
    const uint64_t dropped = total_ - head_.size() - tail.size();
    if (dropped == 0) return head_ + tail;
    return head_ + "\n[... pt-grade kept the first " + std::to_string(head_max_ >> 10) + " KiB and the last " +
           std::to_string(tail_max_ >> 10) + " KiB: " + std::to_string(dropped) + " bytes not kept ...]\n" + tail;
  }

 private:
  size_t head_max_, tail_max_;
  std::string head_, tail_;
  uint64_t total_ = 0;
};

}  // namespace pt::grade
