#include "support/graded.h"

namespace pt::grading {

std::vector<GradedTest>& registry() {
  static std::vector<GradedTest> tests;
  return tests;
}

bool register_test(const char* suite, const char* name, const char* task, double points, Visibility v,
                   bool extension) {
  registry().push_back({suite, name, task, points, v, extension});
  return true;
}

const GradedTest* find(const std::string& suite, const std::string& name) {
  for (const auto& t : registry())
    if (t.suite == suite && t.name == name) return &t;
  return nullptr;
}

}  // namespace pt::grading
