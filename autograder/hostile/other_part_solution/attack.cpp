// Hostile: a task done by another part's solution. Part 1 is graded with
// Part 5's solution linked beside it, and raytrace_pixel_adaptive with its
// stopping rule off (a tolerance of 0: no pixel ever stops early) takes
// exactly ns_aa samples through the pixel, as raytrace_pixel must: P1T2
// scored 4.5 points with no pixel loop of its own.
#include "render/pathtracer.h"

namespace {
pt::PixelEstimate by_adaptive_loop(const pt::PathTracer& tracer, int x, int y, pt::Rng& rng) {
  pt::PathTracer copy = tracer;
  copy.settings.max_tolerance = 0;
  return copy.raytrace_pixel_adaptive(x, y, rng);
}
}  // namespace
