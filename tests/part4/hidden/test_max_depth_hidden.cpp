// Hidden P4T1 test: max_ray_depth is a hard limit and every bounce it allows
// is taken, on mirror chains (exact, no statistics).
#include "../common.h"
#include "../mirror_checks.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

GRADED_TEST(MaxDepth, IsNeverExceededAndEveryBounceIsTaken, "P4T1", 2, Hidden) {
  for (int mirrors = 1; mirrors <= 3; ++mirrors) {
    const MirrorChain chain = make_mirror_chain(mirrors);
    const double card = chain.card_radiance;
    const uint64_t seed = test::seed(4400 + 10 * mirrors);
    // One bounce short of the card: nothing, with or without Russian roulette.
    EXPECT_TRUE(all_equal(chain, chain_settings(mirrors, 1.0, true), 0.0, seed))
        << "max_ray_depth = " << mirrors << " must not reach bounce " << mirrors + 1;
    EXPECT_TRUE(all_equal(chain, chain_settings(mirrors, 0.5, true), 0.0, seed + 1))
        << "Russian roulette must not extend a path past max_ray_depth";
    // Exactly deep enough: the card's light, through weights of exactly 1.
    EXPECT_TRUE(all_equal(chain, chain_settings(mirrors + 1, 1.0, true), card, seed + 2))
        << "max_ray_depth = " << mirrors + 1 << " must reach bounce " << mirrors + 1
        << " (each mirror's weight f cos / pdf is exactly 1)";
    // Bounce isolation: the card's light is bounce mirrors + 1 and no other.
    EXPECT_TRUE(all_equal(chain, chain_settings(mirrors + 1, 1.0, false), card, seed + 3))
        << "accumulate_bounces off: bounce " << mirrors + 1 << " alone is the card's light";
    for (int k = 1; k <= mirrors; ++k)
      EXPECT_TRUE(all_equal(chain, chain_settings(k, 1.0, false), 0.0, seed + 4 + k))
          << "accumulate_bounces off: bounce " << k << " alone is dark";
  }
}

}  // namespace
}  // namespace pt
