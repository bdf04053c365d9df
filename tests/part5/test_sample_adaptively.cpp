// Part 5 graded tests: the adaptive stopping rule, sample_adaptively (P5T1).
//
// Every test feeds a scripted sample sequence, so the exact number of samples
// the rule takes is known in advance. The closed form used throughout:
//
//   Take a sequence that repeats a pattern of P illuminance values with mean mu
//   and population variance sp^2 (the plain average of (x - mu)^2 over the
//   pattern). At any n that is a multiple of P,
//     s1 = n mu,  s2 = n (mu^2 + sp^2),  s2 - s1^2/n = n sp^2,
//     sigma^2 = n sp^2 / (n - 1),
//   so the rule 1.96 sigma / sqrt(n) <= tol mu reads 1.96 sp / sqrt(n - 1) <= tol mu:
//
//     stop at the first checked n (a multiple of the batch size) with
//     n - 1 >= T,   T = (1.96 sp / (tol mu))^2,
//
//   or at max_samples. For a, b alternating, mu = (a+b)/2 and sp = |a-b|/2.
//
// Grey samples (v, v, v) have illuminance v, since the Rec. 709 weights sum to 1.
// Every sequence below is chosen so that the checks either side of the
// expected stop miss the threshold by at least 1% (far beyond round-off).
#include <cmath>

#include "scripted.h"
#include "support/graded.h"

namespace pt {
namespace {

using test::part5::alternating;
using test::part5::constant;
using test::part5::grey;
using test::part5::Outcome;
using test::part5::periodic;
using test::part5::run_script;
using test::part5::Script;

// Sample i has illuminance il(i) but a colour that drifts with i (the tint
// directions w1 and w2 have zero illuminance), so that the mean colour of n
// samples differs for every n and is not a grey.
Script tinted(const std::string& text, std::function<double(int)> il) {
  const Spectrum w1(0.7152, -0.2126, 0.0), w2(0.0, 0.0722, -0.7152);
  return {text + ", tinted: sample i = il(i) * ((1,1,1) + min(i,200)/250 * (0.7152,-0.2126,0) + (i%3)/4 * "
                 "(0,0.0722,-0.7152))",
          [il, w1, w2](int i) {
            double t = std::min(i, 200) / 250.0, u = (i % 3) / 4.0;
            return il(i) * (Spectrum(1.0) + t * w1 + u * w2);
          }};
}

GRADED_TEST(SampleAdaptively, ConstantPixelStopsAfterFirstBatch, "P5T1", 1, Visible) {
  // sigma = 0, so the rule 0 <= tol mu holds at the first check: one batch.
  // Round-off can make s2 - s1^2/n a tiny negative number (it does for some of
  // these colours): clamp the variance at 0, or sqrt gives NaN and the pixel
  // never stops.
  const struct {
    Spectrum c;
    int batch;
  } cases[] = {{grey(0.5), 8}, {Spectrum(0.8, 0.3, 0.1), 16}, {grey(0.7), 8}, {Spectrum(2.0, 1.0, 0.5), 32},
               {Spectrum(0.3, 0.5, 0.7), 64}};
  for (const auto& k : cases)
    EXPECT_STOPS_AT(constant(k.c), 1024, k.batch, 0.05, k.batch,
                    "a constant pixel has zero variance (round-off can make s2 - s1^2/n slightly negative: "
                    "clamp sigma^2 at 0, or sqrt gives NaN and the rule never holds)");
}

GRADED_TEST(SampleAdaptively, NoisyPixelStopsAtFirstBatchMeetingTheRule, "P5T1", 1.5, Visible) {
  // Alternating 3, 1: mu = 2, sp = 1; tol = 0.16:
  //   T = (1.96 * 1 / (0.16 * 2))^2 = 6.125^2 = 37.52.
  // Batch 8: n = 32 has n - 1 = 31 < 37.52 (half-width 1.96/sqrt(31) = 0.352 > tol mu = 0.32),
  //          n = 40 has n - 1 = 39 >= 37.52 (half-width 1.96/sqrt(39) = 0.314 <= 0.32): stop at 40.
  EXPECT_STOPS_AT(alternating(grey(3), grey(1)), 1000, 8, 0.16, 40,
                  "T = (1.96 sp / (tol mu))^2 = 37.52 with mu = 2, sp = 1; first multiple of 8 with n - 1 >= T");
  // Repeating 0.5, 1, 1.5, 3: mu = 1.5, sp^2 = (1 + 0.25 + 0 + 2.25)/4 = 0.875; tol = 0.1:
  //   T = 1.96^2 * 0.875 / (0.1 * 1.5)^2 = 3.3614 / 0.0225 = 149.40.
  // Batch 16: n = 144 has 143 < 149.40 (half-width 0.1533 > 0.15), n = 160 has 159 >= 149.40
  // (half-width 0.1454 <= 0.15): stop at 160.
  EXPECT_STOPS_AT(periodic({grey(0.5), grey(1), grey(1.5), grey(3)}), 1000, 16, 0.1, 160,
                  "T = 149.40 with mu = 1.5, sp^2 = 0.875; first multiple of 16 with n - 1 >= T");
}

GRADED_TEST(SampleAdaptively, NeverTakesMoreThanMaxSamples, "P5T1", 1, Visible) {
  // Alternating 1, 0: mu = 0.5, sp = 0.5; tol = 0.05: T = (1.96 * 0.5 / 0.025)^2 = 1536.6,
  // so no cap below is ever reached by the rule: each run takes exactly max_samples,
  // also when max_samples is not a multiple of the batch size (20, 5, 1).
  for (int cap : {64, 20, 24, 5, 1})
    EXPECT_STOPS_AT(alternating(grey(1), grey(0)), cap, 8, 0.05, cap,
                    "the rule needs n > 1537 here, so the pixel must stop at max_samples exactly");
}

GRADED_TEST(SampleAdaptively, BlackPixelStopsAfterFirstBatch, "P5T1", 0.5, Visible) {
  // mu = 0 and sigma = 0: the rule 0 <= tol * 0 holds, so a black pixel stops
  // after one batch; nothing may divide by mu (0/0 is NaN, and NaN <= x is false).
  for (int batch : {8, 32}) {
    Outcome o = run_script(constant(Spectrum(0.0)), 512, batch, 0.05);
    EXPECT_EQ(o.estimate.num_samples, batch) << o.inputs << "\na black pixel (mu = 0, sigma = 0) stops after one batch";
    EXPECT_EQ(o.calls, o.estimate.num_samples) << o.inputs << "\nthe count must equal the number of next_sample calls";
    EXPECT_TRUE(is_finite(o.estimate.radiance) && o.estimate.radiance == Spectrum(0.0))
        << o.inputs << "\nreturned mean " << o.estimate.radiance << ", expected exactly (0, 0, 0)";
  }
}

GRADED_TEST(SampleAdaptively, ChecksOnlyAtWholeBatches, "P5T1", 1, Visible) {
  // A constant pixel meets the rule from n = 2 on, but the first check is at
  // the end of the first batch.
  EXPECT_STOPS_AT(constant(Spectrum(0.25, 0.5, 1.0)), 1000, 16, 0.05, 16,
                  "the rule holds from n = 2 but is checked only at the end of a batch");
  // Alternating 3, 1 with tol = 0.16 (T = 37.52 as above) meets the rule from
  // n = 39 on, in the middle of the 4th batch of 12: checks at 12, 24, 36
  // (35 < 37.52) fail, the check at 48 (47 >= 37.52) passes.
  EXPECT_STOPS_AT(alternating(grey(3), grey(1)), 1000, 12, 0.16, 48,
                  "the rule first holds around n = 39-40, mid-batch; the next whole batch ends at 48");
}

GRADED_TEST(SampleAdaptively, ReturnsMeanColourOfExactlyTheSamplesTaken, "P5T1", 1, Visible) {
  // The illuminance follows the sequences above (so the stopping counts are the
  // same), the colours drift: the mean must be the mean colour of exactly the
  // samples taken (expect_stops_at compares it with the sum of the first n
  // samples divided by n).
  EXPECT_STOPS_AT(tinted("il(i) = 3, 1, 3, 1, ...", [](int i) { return i % 2 == 0 ? 3.0 : 1.0; }), 1000, 8, 0.16,
                  40, "illuminance alternates 3, 1: T = 37.52, stop at 40");
  EXPECT_STOPS_AT(tinted("il(i) = 0.5 for all i", [](int) { return 0.5; }), 1000, 8, 0.05, 8,
                  "constant illuminance: stop after one batch");
  EXPECT_STOPS_AT(tinted("il(i) = 1, 0, 1, 0, ...", [](int i) { return i % 2 == 0 ? 1.0 : 0.0; }), 20, 8, 0.05, 20,
                  "illuminance alternates 1, 0: T = 1536.6, stop at max_samples = 20");
}

GRADED_TEST(SampleAdaptively, RarelyLitPixelStopsAfterBlackFirstBatch, "P5T1", 0.5, Visible) {
  // The known failure mode (handout, "When it fails"): this pixel sees a bright
  // light in one sample of every 64 (samples 40, 104, 168, ...), so its true
  // value is 1000/64 = 15.6, but its first batch of 16 is all black: mu = 0,
  // sigma = 0, the rule holds and the pixel stops, reported black.
  Script rare{"0 except (1000, 1000, 1000) at samples 40, 104, 168, ... (i % 64 == 40)",
              [](int i) { return i % 64 == 40 ? grey(1000) : grey(0); }};
  Outcome o = run_script(rare, 1024, 16, 0.05);
  EXPECT_EQ(o.estimate.num_samples, 16)
      << o.inputs << "\nthe first batch is all black, so the rule (0 <= tol * 0) stops the pixel after it";
  EXPECT_EQ(o.calls, o.estimate.num_samples) << o.inputs << "\nthe count must equal the number of next_sample calls";
  EXPECT_TRUE(o.estimate.radiance == Spectrum(0.0))
      << o.inputs << "\nreturned " << o.estimate.radiance << ": the 16 samples taken are all black";
}

GRADED_TEST(SampleAdaptively, ACapOfZeroOrLessTakesNoSample, "P5T1", 0.5, Visible) {
  // "Never call next_sample more than max_samples times": with a cap of 0, or
  // below, not even once (a do-while loop draws one sample before it looks at
  // the cap). No sample: n = 0 and the mean of nothing is black, not 0/0.
  // Exact: no statistics.
  for (int cap : {0, -1, -64}) {
    Outcome o = run_script(constant(grey(0.5)), cap, 8, 0.05);
    EXPECT_EQ(o.calls, 0) << o.inputs << "\nmax_samples <= 0: next_sample must not be called at all";
    EXPECT_EQ(o.estimate.num_samples, 0) << o.inputs << "\nno sample taken: the count is 0";
    EXPECT_TRUE(o.estimate.radiance == Spectrum(0.0))
        << o.inputs << "\nreturned " << o.estimate.radiance << ": with no sample the estimate is black (0, 0, 0)";
  }
}

}  // namespace
}  // namespace pt
