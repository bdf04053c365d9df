#pragma once
// Declaring a graded test:
//
//   GRADED_TEST(TriangleIntersect, HitsInterior, "P1T3", 2, Visible) { ... }
//   GRADED_TEST_F(SomeFixture, Name, "P2T3", 1, Hidden) { ... }
//   GRADED_EXTENSION_TEST(Suite, Name, "P5T3", 1, Visible) { ... }
//
// An extension test (an optional task, such as P5T3) is graded like any
// other, but its points count only when the instructor asks for them
// (`pt-grade ... --count-extensions`); otherwise it is reported at 0 points.
//
// The test is an ordinary GoogleTest test; the macro also registers its task,
// points and visibility so that the test main can record them
// (RecordProperty "points", "task", "visibility") and list them
// (`--pt_list_graded`): the grader's build lists the all-reference binaries
// into its manifest, and never asks a binary under test.
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace pt::grading {

enum class Visibility { Visible, Hidden };
constexpr Visibility Visible = Visibility::Visible;
constexpr Visibility Hidden = Visibility::Hidden;

struct GradedTest {
  std::string suite, name, task;
  double points;
  Visibility visibility;
  bool extension = false;
  std::string full_name() const { return suite + "." + name; }
};

std::vector<GradedTest>& registry();
bool register_test(const char* suite, const char* name, const char* task, double points, Visibility v,
                   bool extension = false);
const GradedTest* find(const std::string& suite, const std::string& name);

}  // namespace pt::grading

#define PT_GRADED_REGISTER_(Suite, Name, Task, Points, Vis, Extension)                                  \
  [[maybe_unused]] static const bool pt_graded_##Suite##_##Name##_ =                                    \
      ::pt::grading::register_test(#Suite, #Name, Task, Points, ::pt::grading::Vis, Extension)

#define GRADED_TEST(Suite, Name, Task, Points, Vis) \
  PT_GRADED_REGISTER_(Suite, Name, Task, Points, Vis, false); \
  TEST(Suite, Name)

#define GRADED_TEST_F(Fixture, Name, Task, Points, Vis) \
  PT_GRADED_REGISTER_(Fixture, Name, Task, Points, Vis, false); \
  TEST_F(Fixture, Name)

#define GRADED_EXTENSION_TEST(Suite, Name, Task, Points, Vis) \
  PT_GRADED_REGISTER_(Suite, Name, Task, Points, Vis, true);  \
  TEST(Suite, Name)
