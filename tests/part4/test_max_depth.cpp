// The first bounce is always taken, even under Russian roulette (P4T2).
//
// The mirror chain (support/part4_scenes.h) makes each bounce observable
// without noise: light reaches the eye only after exactly mirrors + 1
// bounces, so with max_ray_depth <= mirrors the estimate is exactly 0 (a
// path that goes one vertex too deep picks up the card's light), and with
// max_ray_depth = mirrors + 1 it is exactly the card's radiance (every
// mirror's weight f cos / pdf is exactly 1). No statistics are needed: each
// check is an equality on every one of 200 estimates, which a correct
// solution passes with probability 1 (whatever its random numbers: the
// mirrors are deterministic, and the card's direct light from a point light
// is exact), up to rounding (relative 1e-6 allowed).
#include <cmath>

#include "common.h"
#include "mirror_checks.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

GRADED_TEST(RussianRoulette, FirstBounceIsAlwaysTaken, "P4T2", 2, Visible) {
  // With a continuation probability as small as 1e-3, the first indirect
  // bounce (from the first hit) is still always taken when the depth allows:
  // roulette starts with the second.
  //
  // (1) Mirror chain of one mirror, max_ray_depth 2: exactly the card's
  // radiance in every estimate (a roulette on the first bounce would return
  // 0 for 999 estimates in 1000 and 1000 times the radiance for the rest).
  const MirrorChain chain = make_mirror_chain(1);
  EXPECT_TRUE(all_equal(chain, chain_settings(2, 1e-3, true), chain.card_radiance, test::seed(4500)));
  EXPECT_TRUE(all_equal(chain, chain_settings(2, 1e-3, false), chain.card_radiance, test::seed(4501)));

  // (2) White furnace, a = 0.5, bounce 2 alone (max_ray_depth 2, accumulate
  // off), p = 1e-3: every estimate is a times the direct light at vertex 2,
  // and the mean is Le a^2 (t test at kAlphaTest, n = 20000, bounded
  // estimator: bounce 2 alone lies in [0, 2 a^2 Le]). An estimate is 0 only
  // by accident: a hemisphere sample exactly on the horizon (chance 2^-32), or
  // vertex 2 within kRayEpsilon of an edge of the box, where a shadow ray
  // starting kRayEpsilon along may begin beyond the neighbouring wall and
  // escape. The strips within 1e-5 of the box's 12 edges have area
  // 12 * 2 * 2e-5 = 4.8e-4, hit from vertex 1 with a density per unit area
  // cos cos' / (pi d^2) below 0.4 (d >= 0.9 to every edge that vertex 1 sees
  // at a non-grazing angle), so fewer than 2e-4 of the estimates are 0
  // (about 4 of 20000; the reference showed 1 in 400000). A roulette on the
  // first bounce makes 99.9% of them 0. The check allows 1% (200): a correct
  // solution exceeds it with probability below 1e-100, the mutant by two
  // orders of magnitude. Power of the mean check (99%): a bias of 2.7%.
  Scene furnace = make_white_furnace(0.5, kLe);
  const Aim target = furnace_aim(furnace);
  PathTracer tracer(furnace, furnace_settings(2, 1e-3, false));
  Rng rng(test::seed(4502));
  stats::RunningStats st;
  int zeros = 0;
  for (int i = 0; i < 20000; ++i) {
    const double L = illuminance(estimate_once(tracer, target, Entry::AtLeastOneBounce, rng));
    zeros += L == 0.0;
    st.add(L);
  }
  EXPECT_LE(zeros, 200) << "estimates of bounce 2 alone that were exactly 0, out of 20000, with rr_continue_prob = "
                           "1e-3: the first bounce must not be subject to Russian roulette";
  EXPECT_TRUE(stats::mean_matches(st, furnace_bounces(0.5, 2, 2), kAlphaTest,
                                  "bounce 2 alone in the furnace (a = 0.5), rr_continue_prob = 1e-3"));
}

GRADED_TEST(RussianRoulette, DecidesFromTheSecondBounceOn, "P4T2", 1, Visible) {
  // Roulette decides about the second bounce and every later one: no sooner
  // (FirstBounceIsAlwaysTaken) and no later. A mirror chain of k mirrors at
  // max_ray_depth k + 1 with p = 0.5 passes k - 1 roulettes (before bounces
  // 2 .. k), so every estimate is either 0 (the path was ended) or exactly
  // card / p^(k-1) (it survived each and was divided by p each time).
  // Exempting two bounces leaves a path that only ever reaches card / p^(k-2)
  // (and always card with one mirror less), which this rules out exactly.
  // Of 200 estimates at least one of each kind is expected: a correct
  // solution sees none survive with probability (1 - p^(k-1))^200 < 1e-24,
  // none ended with probability below 1e-60.
  const double p = 0.5;
  for (const int mirrors : {2, 3}) {
    for (const bool accumulate : {true, false}) {
      const MirrorChain chain = make_mirror_chain(mirrors);
      const RenderSettings s = chain_settings(mirrors + 1, p, accumulate);
      const double survivor = chain.card_radiance / std::pow(p, mirrors - 1);
      PathTracer tracer(chain.scene, s);
      Rng rng(test::seed(4510 + 2 * mirrors + accumulate));
      int ended = 0, survived = 0;
      for (int i = 0; i < kRepeats; ++i) {
        const Spectrum L = estimate_once(tracer, chain.first, Entry::AtLeastOneBounce, rng);
        const bool grey = L.r == L.g && L.g == L.b;
        if (grey && L.r == 0.0) {
          ++ended;
        } else if (grey && std::abs(L.r - survivor) <= 1e-6 * survivor) {
          ++survived;
        } else {
          FAIL() << "mirror chain of " << mirrors << " mirrors, " << describe(s) << ": an estimate was " << L
                 << ", expected 0 or card / p^" << mirrors - 1 << " = " << survivor << " (card's radiance "
                 << chain.card_radiance << "): roulette applies before every bounce from the second on, "
                 << mirrors - 1 << " times on this path"
                 << (std::abs(L.r - survivor * p) <= 1e-6 * survivor ? " (this path passed one roulette too few)" : "");
        }
      }
      EXPECT_GT(survived, 0) << "mirror chain of " << mirrors << " mirrors, " << describe(s) << ": no path survived";
      EXPECT_GT(ended, 0) << "mirror chain of " << mirrors << " mirrors, " << describe(s)
                          << ": no path was ended by roulette in " << kRepeats << " estimates";
    }
  }
}

}  // namespace
}  // namespace pt
