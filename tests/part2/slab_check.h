#pragma once
// The slab-test check shared by the P2T2 tests (BBox::intersect): runs the
// student's test with an incoming [t0, t1] and compares the answer and the
// narrowed interval with the expected ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geometry/bbox.h"

namespace pt::test::part2 {

// Most cases use numbers that are exact in binary floating point, so that
// division by d and multiplication by 1/d agree; 1e-12 only absorbs the last bit.
constexpr double kSlabTol = 1e-12;

// The box of most cases: x in [-1, 1], y in [-2, 2], z in [-3, 3].
inline const BBox kBox(Vec3(-1, -2, -3), Vec3(1, 2, 3));

// Runs the student's slab test with incoming [t0, t1] and checks the outcome.
inline testing::AssertionResult slab(const BBox& box, const Ray& r, double t0, double t1, bool expect_hit,
                                     double e0 = 0.0, double e1 = 0.0) {
  double a = t0, b = t1;
  bool hit = box.intersect(r, a, b);
  std::ostringstream os;
  os.precision(17);
  os << "box " << box << ", ray o=" << r.o << " d=" << r.d << ", incoming [t0, t1] = [" << t0 << ", " << t1 << "]: ";
  if (hit != expect_hit) {
    os << "returned " << (hit ? "true (hit)" : "false (miss)") << ", expected " << (expect_hit ? "a hit" : "a miss");
    if (expect_hit) os << " with [t0, t1] = [" << e0 << ", " << e1 << "]";
    return testing::AssertionFailure() << os.str();
  }
  if (!hit) return testing::AssertionSuccess();
  auto close = [](double x, double y) {
    if (std::isinf(y)) return x == y;
    return std::abs(x - y) <= kSlabTol * std::max(1.0, std::abs(y));
  };
  if (!close(a, e0) || !close(b, e1)) {
    os << "hit, but narrowed the interval to [" << a << ", " << b << "], expected [" << e0 << ", " << e1 << "]";
    return testing::AssertionFailure() << os.str();
  }
  return testing::AssertionSuccess();
}

inline Ray ray(const Vec3& o, const Vec3& d) { return Ray(o, d); }

}  // namespace pt::test::part2
