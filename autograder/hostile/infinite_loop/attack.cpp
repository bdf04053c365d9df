// Hostile (or just broken): an infinite loop in one task. raytrace_pixel never
// returns; each of its tests may cost only itself and the per-test time limit.
namespace {
volatile bool forever = true;
}  // namespace
