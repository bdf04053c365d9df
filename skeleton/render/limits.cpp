#include "render/limits.h"

#include <cmath>

namespace pt {

namespace {

std::string outside(const char* what, long long v, long long lo, long long hi) {
  return std::string(what) + " " + std::to_string(v) + " is not in [" + std::to_string(lo) + ", " +
         std::to_string(hi) + "]";
}

}  // namespace

std::string check_render_limits(const RenderSettings& s, int threads) {
  if (s.width < 1 || s.width > kMaxImageSide) return outside("image width", s.width, 1, kMaxImageSide);
  if (s.height < 1 || s.height > kMaxImageSide) return outside("image height", s.height, 1, kMaxImageSide);
  if ((long long)s.width * s.height > kMaxPixels)
    return "image of " + std::to_string((long long)s.width * s.height) + " pixels (" + std::to_string(s.width) +
           "x" + std::to_string(s.height) + "): at most " + std::to_string(kMaxPixels) +
           " (about 40 bytes of memory each)";
  if (s.ns_aa < 1 || s.ns_aa > kMaxSamples) return outside("samples per pixel", s.ns_aa, 1, kMaxSamples);
  if (s.ns_area_light < 1 || s.ns_area_light > kMaxLightSamples)
    return outside("light samples", s.ns_area_light, 1, kMaxLightSamples);
  if (s.max_ray_depth < 0 || s.max_ray_depth > kMaxRayDepth)
    return outside("maximum ray depth", s.max_ray_depth, 0, kMaxRayDepth);
  if (s.samples_per_batch < 1 || s.samples_per_batch > kMaxSamples)
    return outside("samples per batch", s.samples_per_batch, 1, kMaxSamples);
  if (s.adaptive_budget != 0 && (s.adaptive_budget < kMinAdaptiveBudget || s.adaptive_budget > kMaxSamples))
    return outside("adaptive budget (samples per pixel)", s.adaptive_budget, kMinAdaptiveBudget, kMaxSamples);
  if (s.adaptive_rounds < 1 || s.adaptive_rounds > kMaxAdaptiveRounds)
    return outside("adaptive rounds", s.adaptive_rounds, 1, kMaxAdaptiveRounds);
  if (s.adaptive_budget != 0 && s.adaptive)
    return "the adaptive budget and the adaptive stopping rule (-a) are two different samplers: choose one";
  if (threads < 1 || threads > kMaxThreads) return outside("threads", threads, 1, kMaxThreads);
  if (!(s.rr_continue_prob > 0.0 && s.rr_continue_prob <= 1.0))
    return "Russian roulette continuation probability " + std::to_string(s.rr_continue_prob) + " is not in (0, 1]";
  if (!(std::isfinite(s.max_tolerance) && s.max_tolerance >= 0.0))
    return "adaptive tolerance " + std::to_string(s.max_tolerance) + " is not a finite number >= 0";
  return "";
}

}  // namespace pt
