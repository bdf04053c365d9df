#pragma once
// Assertions every part's tests share: each names the quantity and shows what
// it got against what it expected, so a failure reads without the source.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/vec.h"

namespace pt::test {

// `text` contains `part` (an error message names the file, the place, ...).
inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// `what` = actual, within tol of expected in every component.
inline ::testing::AssertionResult VecNear(const char* what, const Vec3& actual, const Vec3& expected, double tol) {
  if (is_finite(actual) && glm::all(glm::lessThanEqual(glm::abs(actual - expected), Vec3(tol))))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << " is " << actual << ", expected " << expected << " (tolerance "
                                       << tol << " per component)";
}

// `what` = actual, within tol of expected.
inline ::testing::AssertionResult Near(const char* what, double actual, double expected, double tol) {
  if (std::abs(actual - expected) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << " is " << actual << ", expected " << expected << " (tolerance "
                                       << tol << ")";
}

}  // namespace pt::test
