// Russian roulette (P4T2): each bounce after the first continues with
// probability p = settings.rr_continue_prob and the survivors are divided by
// p, so the mean is unchanged, E[X'] = p * (X / p) + (1 - p) * 0 = E[X], and
// the variance rises. Tested in the white furnace, where the mean is known in
// closed form (common.h, support/part4_scenes.h).
#include "common.h"
#include "support/graded.h"

namespace pt {
namespace {

using namespace test::part4;

GRADED_TEST(RussianRoulette, KeepsTheMean, "P4T2", 2, Visible) {
  // at_least_one_bounce_radiance with roulette against the closed form
  // Le (a + ... + a^m). Two-sided t tests, n = 50000, alpha_each(4) each.
  // The estimators are bounded or exponentially tailed: with p = a every
  // path weight a^k / p^(k-1) is at most 1 and the path length is geometric;
  // with (a, p, m) = (0.8, 0.5, 5) the weight is at most 0.8^4 / 0.5^3 = 3.3.
  // Relative standard deviations (closed form) 0.6 at most: standard error
  // below 0.3% of the mean. Power: forgetting to divide by p gives
  // 1.5 (0.5 + 0.25 + 0.083) = 1.25 instead of 1.5 for (0.5, 0.5) (-17%,
  // about 70 standard errors); continuing with probability 1 - p instead of
  // p is off by factors (0.2/0.8)^k for (0.8, 0.8); both are also far off
  // in the other cases. Power (99%): a bias of 1.5% (a = 0.3) to 2.4%.
  struct Case {
    double a, p;
    int m;
  };
  const Case cases[] = {{0.5, 0.5, 1000}, {0.8, 0.8, 1000}, {0.3, 0.3, 1000}, {0.8, 0.5, 5}};
  const double alpha = alpha_each(4);
  uint64_t seed = 4600;
  for (const Case& c : cases) {
    Scene scene = make_white_furnace(c.a, kLe);
    const RenderSettings s = furnace_settings(c.m, c.p);
    stats::RunningStats st = sample(scene, furnace_aim(scene), s, Entry::AtLeastOneBounce, 50000, test::seed(seed++));
    std::ostringstream what;
    what << "at_least_one_bounce_radiance in the furnace, albedo " << c.a << ", " << describe(s);
    EXPECT_TRUE(stats::mean_matches(st, furnace_bounces(c.a, 1, c.m), alpha, what.str()))
        << "Russian roulette must leave the mean unchanged: survivors are divided by p";
  }

  // ... and roulette ends paths, as the answers show: with accumulate_bounces
  // off, bounce 6 alone (a = 0.8, p = 0.5) reaches the eye only along a path
  // that survived roulette at vertices 2 to 5, with probability p^4 = 1/16;
  // every other estimate is exactly 0. Without roulette every path reaches
  // vertex 6 and is 0 only if it escaped through the strips along the box's
  // edges (below 2e-4 of them, RussianRoulette.FirstBounceIsAlwaysTaken).
  // The check asks for at least a quarter of 20000 estimates to be 0: a
  // correct solution (3/4 of them 0 even if its roulette starts two bounces
  // late) falls short with probability below 1e-100 (Chernoff), one without
  // roulette (about 4 zeros) never reaches it. Counted from the estimates
  // themselves, so that it holds whatever the path guard saw.
  Scene scene = make_white_furnace(0.8, kLe);
  const Aim target = furnace_aim(scene);
  PathTracer tracer(scene, furnace_settings(6, 0.5, /*accumulate=*/false));
  Rng rng(test::seed(seed++));
  const int n = 20000;
  int zeros = 0;
  for (int i = 0; i < n; ++i) zeros += illuminance(estimate_once(tracer, target, Entry::AtLeastOneBounce, rng)) == 0.0;
  EXPECT_GE(zeros, n / 4) << "estimates of bounce 6 alone that were exactly 0, out of " << n
                          << ", in the furnace (a = 0.8) with rr_continue_prob = 0.5: a path survives roulette at "
                             "vertices 2 to 5 with probability 1/16, so most of them must be 0; with none, Russian "
                             "roulette is not ending paths";
}

}  // namespace
}  // namespace pt
