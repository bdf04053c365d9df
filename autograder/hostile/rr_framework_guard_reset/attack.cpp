// Hostile: Part 4's tests count the BSDF samples of each path in a path guard,
// which stops a path longer than roulette lets one be. The guard and the
// BSDFs that count in it are the framework's (skeleton/scene/path_guard.h), so
// that the worker rebuilds the very BSDFs the tests made: the worker's guard
// is then the framework's path_guard(), which a task file may call. This one
// empties it after every sample. Its paths have no roulette at depths 6 to
// 1000 with p <= 0.5 (elsewhere they keep it, as in rr_guard_reset); they end
// after 40 bounces, past the guard's limit for p = 0.3 (37). The guard only
// stops paths and credits nothing: RussianRoulette.KeepsTheMean grades
// roulette from the estimates themselves, and the hidden RaisesTheVariance
// sees no variance rise; both fail, whatever the worker's guard says.
#include "render/settings.h"
#include "scene/path_guard.h"

namespace {
bool roulette_skipped(const pt::RenderSettings& s) {
  return s.max_ray_depth > 5 && s.max_ray_depth <= 1000 && s.rr_continue_prob <= 0.5;
}

// Called after each sample, `bounces` bounces into the path.
bool path_ends_unguarded(int bounces) {
  pt::path_guard().samples = 0;
  return bounces >= 40;
}
}  // namespace
