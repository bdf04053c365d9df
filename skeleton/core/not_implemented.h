#pragma once
#include <stdexcept>
#include <string>

namespace pt {

// Thrown by every untouched task stub. The message names the task tag so that a
// failing test says which function is missing, e.g.
//   not implemented: P1T3 Triangle::intersect
class NotImplemented : public std::logic_error {
 public:
  explicit NotImplemented(const std::string& task) : std::logic_error("not implemented: " + task) {}
};

}  // namespace pt
