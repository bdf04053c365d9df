// The stand-ins of support/compiled/ (the baseline BVH builder and the ordered
// traversal, near-solutions that the release ships compiled only) in a release
// built on a platform it has no prebuilt libraries for (PT_NO_PREBUILT_FOR,
// the top-level CMakeLists): the tests that need them link, and fail saying why.
#include <stdexcept>
#include <string>

#include "support/bvh_checks.h"
#include "support/part2_baseline.h"

namespace pt::test::part2 {
namespace {

[[noreturn]] void absent(const char* what) {
  throw std::runtime_error(std::string(what) +
                           " is part of the course's compiled test support (prebuilt/), which this release does not "
                           "have for " PT_NO_PREBUILT_FOR ": this test cannot run here (prebuilt/README.md)");
}

}  // namespace

const char* method_name(SplitMethod) { return "the handout's baseline (not in this build)"; }

FlatTree build_framework_bvh(std::vector<const Primitive*>, size_t, SplitMethod) {
  absent("the handout's baseline BVH builder");
}

bool slab_closed(const BBox&, const Ray&, double&, double&) { absent("the framework's slab test"); }

bool framework_closest(const FlatTree&, const Ray&, Intersection*) { absent("the framework's ordered traversal"); }

}  // namespace pt::test::part2
