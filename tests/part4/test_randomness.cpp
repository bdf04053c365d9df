// Part 4's tasks draw their random numbers (bounce directions, roulette
// coins) from the Rng passed in, and only from it (skeleton/render/pathtracer.h,
// handouts/part4.md section 0): two generators in the same state give the same
// answer, and the one passed in moves (support/draws_from.h). Exact
// comparisons; a correct solution fails with probability 2^-32 per call.
// Boundary: the generator's state crosses with each call and comes back with
// its answer.
#include "common.h"
#include "mirror_checks.h"
#include "support/draws_from.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

// The white furnace at depth 3 without roulette: every vertex draws its
// direct light's and its bounce's directions, so the answer is continuous and
// a generator of the task's own shows at the first call.
void check_furnace(Entry e, uint64_t seed) {
  const Scene furnace = make_white_furnace(0.5, kLe);
  const Aim target = furnace_aim(furnace);
  const PathTracer tracer(furnace, furnace_settings(3, 1.0));
  EXPECT_TRUE(test::draws_only_from([&](Rng& rng) { return estimate_once(tracer, target, e, rng); }, test::seed(seed),
                                    4, name(e)));
}

GRADED_TEST(PathRandomness, BounceDirectionsComeOnlyFromItsRng, "P4T1", 0.5, Visible) {
  check_furnace(Entry::AtLeastOneBounce, 4520);
}

GRADED_TEST(PathRandomness, RouletteCoinComesOnlyFromItsRng, "P4T2", 0.5, Visible) {
  // A chain of two mirrors at depth 3, p = 0.5: the mirrors and the point
  // light draw nothing, so the roulette before the second bounce is the only
  // draw, and the answer (0 or card / p) is the coin. A coin of the task's own
  // agrees with the one passed in half the time: 64 calls all alike by chance
  // with probability 2^-64; and it leaves the generator passed in unmoved.
  const MirrorChain chain = make_mirror_chain(2);
  const PathTracer tracer(chain.scene, chain_settings(3, 0.5, true));
  EXPECT_TRUE(test::draws_only_from(
      [&](Rng& rng) { return estimate_once(tracer, chain.first, Entry::AtLeastOneBounce, rng); }, test::seed(4521), 64,
      "at_least_one_bounce_radiance's Russian roulette"));
}

GRADED_TEST(PathRandomness, GlobalEstimateDrawsOnlyFromItsRng, "P4T3", 0.5, Visible) {
  check_furnace(Entry::GlobalIllumination, 4522);
}

}  // namespace
}  // namespace pt
