// Hostile: Part 4's tests count the BSDF samples of each path in a path guard,
// which stops a path longer than roulette lets one be (tests/support/
// part4_scenes.h). When this case was written, the worker's copies of the
// tests' BSDFs counted in a guard of the worker's (path_guard_copy(), in
// pt::boundary), an inline function that any object of the worker could
// define too: this one does, with the same layout, and empties the guard after
// every sample. (The guard is now the framework's, scene/path_guard.h, and
// rr_framework_guard_reset empties that one; this definition, in the
// boundary's namespace, does not build: pt-link-guard refuses it.) Its paths have
// no roulette at depths 6 to 1000 with p <= 0.5 (elsewhere they keep it, so
// that only what roulette's tests see is at stake, not the time limits of
// the Cornell box, depth 5, of Furnace.FullEstimate, p >= 0.7, or of the
// high-albedo test, depth 10,000); they end after 40
// bounces (what the furnace's walls bring back after that is below what the
// mean tests see), past the guard's limit for p = 0.3 (37).
// RussianRoulette.KeepsTheMean now grades roulette from the estimates
// themselves (most estimates of a late bounce alone are 0 when paths end by
// roulette), and the hidden RaisesTheVariance sees no variance rise: both
// fail, whatever the worker's guard says.
#include <cstdint>
#include <stdexcept>

#include "render/settings.h"

namespace pt::boundary {
struct PathGuardCopy {  // the layout of the boundary's old path_guard_copy.h, copied
  int64_t samples = 0;
  int64_t limit = INT64_MAX;
};
inline PathGuardCopy& path_guard_copy() {
  thread_local PathGuardCopy g;
  return g;
}
}  // namespace pt::boundary

namespace {
bool roulette_skipped(const pt::RenderSettings& s) {
  return s.max_ray_depth > 5 && s.max_ray_depth <= 1000 && s.rr_continue_prob <= 0.5;
}

// Called after each sample, `bounces` bounces into the path.
bool path_ends_unguarded(int bounces) {
  pt::boundary::path_guard_copy().samples = 0;
  return bounces >= 40;
}
}  // namespace
