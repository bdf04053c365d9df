// Hostile: the extension task P5T3 answered by the framework. The budgeted
// renderer (--adaptive-budget, render/budget.h) has its own water-filling
// allocator; a task file that declares it and calls it passes every P5T3
// test without writing one. pt-link-guard refuses a task file that uses a
// framework function listed as a task's answer.
#include <cmath>
#include <vector>

#include "render/pathtracer.h"

namespace pt {
std::vector<int> allocate_counts(const std::vector<double>& r, long long total, int floor, int cap);

namespace {
std::vector<int> framework_answer(const std::vector<PilotMoments>& pilot, long long budget) {
  std::vector<double> r;
  for (const auto& p : pilot) r.push_back(std::sqrt(p.variance / (p.mean * p.mean + 1e-2)));
  return allocate_counts(r, budget, 1, 1 << 30);
}
}  // namespace
}  // namespace pt
