#pragma once
// A global that the boundary's callbacks read (the tracer whose pixel is
// sampled, the tape of a call being replayed, the BVH being built or
// traversed), set for the life of one call and then restored: calls nest, as
// a callback may call a task function again.
#include <utility>

namespace pt::boundary {

template <class T>
class Scoped {
 public:
  Scoped(T& global, T value) : global_(global), previous_(std::exchange(global, value)) {}
  ~Scoped() { global_ = previous_; }
  Scoped(const Scoped&) = delete;
  Scoped& operator=(const Scoped&) = delete;

 private:
  T& global_;
  T previous_;
};

}  // namespace pt::boundary
