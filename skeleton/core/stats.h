#pragma once
// Work counters (rays, primitive tests, BVH node visits). Thread-local plain
// integers: an increment is one add on a cache line nobody else touches, so the
// counters stay on in release builds. Tests read them to count work instead of
// timing it; the renderer sums them over its threads.
#include <cstdint>

namespace pt {

struct WorkCounters {
  uint64_t rays = 0;             // rays traced against the scene (camera, bounce and shadow)
  uint64_t primitive_tests = 0;  // ray-primitive intersection tests
  uint64_t node_visits = 0;      // BVH nodes whose box was tested

  WorkCounters& operator+=(const WorkCounters& o) {
    rays += o.rays;
    primitive_tests += o.primitive_tests;
    node_visits += o.node_visits;
    return *this;
  }
};

// This thread's counters. Inline so that a count is one add at a
// thread-local address, cheap enough to stay on around every primitive test.
inline WorkCounters& work_counters() {
  thread_local WorkCounters counters;
  return counters;
}

// Zeroes this thread's counters and returns what they held.
inline WorkCounters take_work_counters() {
  WorkCounters c = work_counters();
  work_counters() = WorkCounters{};
  return c;
}

// Whether the primitive tests of the query running now on this thread are
// read one by one (a test counting a BVH query's work sets it). Where nothing
// reads them, the grader's process boundary may answer several primitive
// tests with one message (autograder/boundary/README.md, "BVHs").
inline bool& primitive_tests_read() {
  thread_local bool read = false;
  return read;
}

}  // namespace pt
