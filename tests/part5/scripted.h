#pragma once
// Scripted pixels for the Part 5 tests: sample sequences fixed in advance, so
// that the exact number of samples the stopping rule takes is known in closed
// form, and no test depends on random numbers.
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/vec.h"
#include "render/pathtracer.h"
#include "scene/scene.h"
#include "support/scripted_tracer.h"

namespace pt::test::part5 {

using test::constant;
using test::Script;
using test::ScriptedTracer;

// A grey sample: illuminance v, since the Rec. 709 weights sum to 1.
inline Spectrum grey(double v) { return Spectrum(v); }

// a, b, a, b, ...
inline Script alternating(const Spectrum& a, const Spectrum& b) {
  std::ostringstream os;
  os << "alternating " << a << ", " << b << ", ... (illuminance " << illuminance(a) << ", " << illuminance(b) << ")";
  return {os.str(), [a, b](int i) { return i % 2 == 0 ? a : b; }};
}

// pattern[0], pattern[1], ..., pattern[P-1], pattern[0], ...
inline Script periodic(const std::vector<Spectrum>& pattern) {
  std::ostringstream os;
  os << "repeating";
  for (const auto& p : pattern) os << " " << p;
  os << " ...";
  return {os.str(), [pattern](int i) { return pattern[size_t(i) % pattern.size()]; }};
}

// Mean colour of samples 0 .. n-1 of a script.
inline Spectrum mean_of_first(const Script& s, int n) {
  Spectrum sum(0.0);
  for (int i = 0; i < n; ++i) sum += s.value(i);
  return n > 0 ? sum / double(n) : Spectrum(0.0);
}

// What sample_adaptively did with a script.
struct Outcome {
  PixelEstimate estimate;
  int calls = 0;       // times next_sample was called
  std::string inputs;  // the call, for failure messages
};

// Runs sample_adaptively on a script, counting the calls of next_sample. An
// implementation that ignores max_samples is stopped (by an exception) after
// max_samples + 1000 calls rather than hanging the test.
inline Outcome run_script(const Script& s, int max_samples, int samples_per_batch, double max_tolerance) {
  Outcome out;
  std::ostringstream in;
  in << "sample_adaptively(next_sample, max_samples=" << max_samples << ", samples_per_batch=" << samples_per_batch
     << ", max_tolerance=" << max_tolerance << ") with next_sample = " << s.text;
  out.inputs = in.str();
  const int guard = max_samples + 1000;
  auto next_sample = [&]() -> Spectrum {
    if (out.calls >= guard)
      throw std::runtime_error("next_sample called " + std::to_string(out.calls) + " times with max_samples=" +
                               std::to_string(max_samples) + ": the loop does not stop at max_samples");
    return s.value(out.calls++);
  };
  out.estimate = sample_adaptively(next_sample, max_samples, samples_per_batch, max_tolerance);
  return out;
}

inline bool spectrum_near(const Spectrum& a, const Spectrum& b, double rel = 1e-9) {
  for (int c = 0; c < 3; ++c)
    if (!(std::abs(a[c] - b[c]) <= rel * std::max(1.0, std::abs(b[c])))) return false;
  return true;
}

// The stopping count, the call count and the mean of exactly the samples taken.
inline void expect_stops_at(const Script& s, int max_samples, int samples_per_batch, double max_tolerance,
                            int expected_n, const std::string& why) {
  Outcome o = run_script(s, max_samples, samples_per_batch, max_tolerance);
  EXPECT_EQ(o.estimate.num_samples, expected_n) << o.inputs << "\nexpected to stop after " << expected_n
                                                << " samples: " << why;
  EXPECT_EQ(o.calls, o.estimate.num_samples)
      << o.inputs << "\nthe returned sample count must equal the number of times next_sample was called";
  Spectrum want = mean_of_first(s, o.calls);
  EXPECT_TRUE(spectrum_near(o.estimate.radiance, want))
      << o.inputs << "\nreturned mean " << o.estimate.radiance << " but the mean of the " << o.calls
      << " samples taken is " << want;
}

// The same, with the caller's line in the failure message.
#define EXPECT_STOPS_AT(...)                                   \
  do {                                                         \
    SCOPED_TRACE("expectation made here");                     \
    ::pt::test::part5::expect_stops_at(__VA_ARGS__);           \
  } while (0)

// The scene of the raytrace_pixel_adaptive tests: no shapes (the scripted
// tracer never intersects anything), a camera that is not at the origin.
inline Scene scene_with_camera() {
  Scene scene;
  scene.camera = Camera(Vec3(1, 2, 3), Vec3(0, 0, 0), Vec3(0, 1, 0), 60.0, 45.0);
  return scene;
}

inline RenderSettings adaptive_settings(int width, int height, int ns_aa, int batch, double tol) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.ns_aa = ns_aa;
  s.adaptive = true;
  s.samples_per_batch = batch;
  s.max_tolerance = tol;
  return s;
}

// The call raytrace_pixel_adaptive(x, y) on a scripted tracer, for failure messages.
inline std::string describe(const ScriptedTracer& t, int x, int y) {
  const RenderSettings& s = t.settings;
  std::ostringstream os;
  os << "raytrace_pixel_adaptive(x=" << x << ", y=" << y << ") with width=" << s.width << ", height=" << s.height
     << ", ns_aa=" << s.ns_aa << ", samples_per_batch=" << s.samples_per_batch
     << ", max_tolerance=" << s.max_tolerance << ", radiance estimate = " << t.script.text;
  return os.str();
}

}  // namespace pt::test::part5
