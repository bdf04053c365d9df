// Hostile: the test support's own traversal in place of the student's. The
// Part 2 tests link the support's linear scan (pt::test::part2::linear_any, what
// the tests compare a BVH's answers with); a task file that declares it can
// call it, and answer every any-hit query correctly without a BVH.
// pt-link-guard refuses a task file that uses what only the tests, their
// support or GoogleTest define.
#include <vector>
namespace pt {
class Primitive;
struct Ray;
namespace test::part2 {
bool linear_any(const std::vector<const Primitive*>& prims, const Ray& r);
}  // namespace test::part2
}  // namespace pt
