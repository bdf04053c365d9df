// Hidden P5T1 tests: the constants of the stopping rule (the unbiased
// variance, the Rec. 709 illuminance, a tolerance relative to the mean), on
// scripted sequences whose exact stopping count is known (the closed form of
// test_sample_adaptively.cpp: stop at the first checked n with n - 1 >= T).
#include "../scripted.h"
#include "support/graded.h"

namespace pt {
namespace {

using test::part5::alternating;
using test::part5::constant;
using test::part5::grey;

GRADED_TEST(SampleAdaptively, VarianceUsesNMinusOne, "P5T1", 0.5, Hidden) {
  // Alternating 1.5, 0.5: mu = 1, sp = 0.5; tol = 0.25: T = (1.96 * 0.5 / 0.25)^2 = 3.92^2 = 15.37.
  // Unbiased (n - 1): stop at the first checked n with n - 1 >= 15.37, i.e. n >= 16.37:
  //   batch 4 -> 20 (at 16 the half-width is 1.96 sqrt(16 * 0.25 / 15 / 16) = 0.2530 > 0.25);
  //   batch 2 -> 18.
  // Dividing by n instead would stop at n >= 15.37, i.e. 16 for both (half-width 0.245).
  EXPECT_STOPS_AT(alternating(grey(1.5), grey(0.5)), 1000, 4, 0.25, 20,
                  "sigma^2 = (s2 - s1^2/n) / (n - 1); with / n the pixel would stop at 16");
  EXPECT_STOPS_AT(alternating(grey(1.5), grey(0.5)), 1000, 2, 0.25, 18,
                  "sigma^2 = (s2 - s1^2/n) / (n - 1); with / n the pixel would stop at 16");
}

GRADED_TEST(SampleAdaptively, UsesRec709Illuminance, "P5T1", 0.5, Hidden) {
  // x_k = illuminance = 0.2126 r + 0.7152 g + 0.0722 b.
  // (a) (0, 1, 0) and (k, 0, k) with k = 0.7152 / 0.2848 have the same
  //     illuminance 0.7152: a constant pixel for the rule, one batch (8).
  //     Their RGB averages (0.333, 1.674) or red channels (0, 2.51) alternate
  //     wildly (T > 600 with tol = 0.05), which would run to the cap of 64.
  const double k = 0.7152 / (0.2126 + 0.0722);
  EXPECT_STOPS_AT(alternating(Spectrum(0, 1, 0), Spectrum(k, 0, k)), 64, 8, 0.05, 8,
                  "both colours have illuminance 0.7152 (Rec. 709 weights): zero variance");
  // (b) (3, 0, 0) and (0, 3, 0) have the same RGB average 1 but illuminance
  //     0.6378 and 2.1456: mu = 1.3917, sp = 0.7539, T = (1.96 * 0.7539 / (0.05 * 1.3917))^2
  //     = 451 > 64, so the pixel runs to the cap (the RGB average would stop at 8).
  EXPECT_STOPS_AT(alternating(Spectrum(3, 0, 0), Spectrum(0, 3, 0)), 64, 8, 0.05, 64,
                  "illuminance alternates 0.6378, 2.1456: T = 451, more than the cap of 64");
}

GRADED_TEST(SampleAdaptively, IlluminanceWeightsFitTheirChannels, "P5T1", 0.5, Hidden) {
  // Each Rec. 709 weight belongs to its own channel: 0.2126 to red, 0.7152 to
  // green, 0.0722 to blue. Colours that differ in two channels only,
  // (1 / 0.2126, 0, 0), (0, 1 / 0.7152, 0) and (0, 0, 1 / 0.0722), all have
  // illuminance 1, so alternating any two of them is a constant pixel for the
  // rule: one batch (8). With the weights on the wrong channels (the five
  // other assignments: B, G, R order, red and green swapped, ...) the
  // alternating values are w'_i / w_i and w'_j / w_j. With tol = 0.05,
  // T = (1.96 (sp / mu) / tol)^2 (stop at the first checked n with n - 1 >= T)
  // is, per assignment, at least 373 on two of the three pairs (and 6.8 on
  // the third for the two cyclic shifts, which is why one pair is not
  // enough: red against blue alone lets (0.7152, 0.0722, 0.2126) stop at 8),
  // so each wrong assignment runs a pair to the cap of 64. Boundary: the
  // stopping count, 8 against 64, exact.
  const Spectrum red(1.0 / 0.2126, 0, 0), green(0, 1.0 / 0.7152, 0), blue(0, 0, 1.0 / 0.0722);
  const char* why =
      "both colours have illuminance 1 (0.2126 r + 0.7152 g + 0.0722 b): zero variance; weights applied to the "
      "wrong channels make the two differ and the pixel run to the cap";
  EXPECT_STOPS_AT(alternating(red, blue), 64, 8, 0.05, 8, why);
  EXPECT_STOPS_AT(alternating(red, green), 64, 8, 0.05, 8, why);
  EXPECT_STOPS_AT(alternating(green, blue), 64, 8, 0.05, 8, why);
}

GRADED_TEST(SampleAdaptively, ToleranceIsRelativeToTheMean, "P5T1", 0.5, Hidden) {
  // Scaling every sample by s scales mu and sigma alike, so T is unchanged:
  // alternating 30, 10 and 0.03, 0.01 (sp / mu = 0.5 as for 3, 1) both stop at
  // 40 with tol = 0.16 and batch 8. Comparing the half-width with tol alone
  // (not tol * mu) would stop the dim pixel at 8 and run the bright one to the cap.
  EXPECT_STOPS_AT(alternating(grey(30), grey(10)), 4096, 8, 0.16, 40,
                  "the rule is relative: 1.96 sigma / sqrt(n) <= tol * mu, T = 37.52 at any scale");
  EXPECT_STOPS_AT(alternating(grey(0.03), grey(0.01)), 4096, 8, 0.16, 40,
                  "the rule is relative: 1.96 sigma / sqrt(n) <= tol * mu, T = 37.52 at any scale");
}

GRADED_TEST(SampleAdaptively, HalfWidthIsSigmaOverSqrtN, "P5T1", 0.5, Hidden) {
  // The half-width is 1.96 sigma / sqrt(n), with sigma^2 already divided by
  // n - 1; dividing by sqrt(n - 1) instead widens it by sqrt(n / (n - 1)),
  // which moves the stop only while n is small. Alternating 3, 1: mu = 2,
  // sp = 1; tol = 0.335: T = (1.96 / 0.67)^2 = 8.558. Batch 2: at n = 8 the
  // half-width is 1.106 tol mu, at n = 10 0.975 tol mu: stop at 10 (with
  // sqrt(n - 1), 1.028 tol mu at 10: stop at 12). Batch 1: at n = 8 1.106,
  // at n = 9 0.974 (odd n: s1 = 2n + 1): stop at 9 (with sqrt(n - 1): 11).
  // Each check either side of the stop misses the rule by 2.5% or more.
  // Boundary: the stopping count, exact.
  EXPECT_STOPS_AT(alternating(grey(3), grey(1)), 1000, 2, 0.335, 10,
                  "T = 8.558: the first even n with n - 1 >= T; with sigma / sqrt(n - 1) the pixel would stop at 12");
  EXPECT_STOPS_AT(alternating(grey(3), grey(1)), 1000, 1, 0.335, 9,
                  "half-width 0.974 tol mu at n = 9; with sigma / sqrt(n - 1) the pixel would stop at 11");
}

GRADED_TEST(SampleAdaptively, BatchOfOneSkipsTheFirstCheck, "P5T1", 0.5, Hidden) {
  // With samples_per_batch = 1 every n is a whole batch, but sigma^2 needs two
  // samples (handout, section 4): the first check is at n = 2. Checked at
  // n = 1, (s2 - s1^2) / 0 is 0 / 0, and a clamp max(0, NaN) or a variance
  // divided by n turns it into 0: every pixel "converges" after one sample.
  // A constant pixel stops at 2; alternating 3, 1 with tol 0.335 at 9 (as
  // in the test above). Boundary: n = 1 against n = 2, exact.
  EXPECT_STOPS_AT(constant(grey(0.5)), 1000, 1, 0.05, 2,
                  "batch size 1: the first check is at n = 2 (sigma^2 needs two samples), where a constant pixel stops");
  EXPECT_STOPS_AT(alternating(grey(3), grey(1)), 1000, 1, 0.335, 9,
                  "batch size 1: no check at n = 1; the rule first holds at n = 9");
}

}  // namespace
}  // namespace pt
