#pragma once
#include <cstdint>

namespace pt {

// What the estimators are asked to do; the command-line flags map onto these
// one to one (the course's short flag in brackets).
struct RenderSettings {
  int width = 480, height = 360;        // [-r w h]
  int ns_aa = 1;                        // [-s] samples per pixel (the cap, when adaptive)
  int ns_area_light = 1;                // [-l] light samples per area light per estimate
  int max_ray_depth = 1;                // [-m] bounces: 0 = emission only, 1 = direct, ...
  bool direct_hemisphere_sample = false;  // [-H] uniform hemisphere instead of light sampling
  bool accumulate_bounces = true;       // [-o] false: keep only bounce number max_ray_depth
  double rr_continue_prob = 0.7;        // Russian roulette continuation probability
  bool adaptive = false;                // [-a] adaptive sampling on
  int samples_per_batch = 32;           // [-a batch tol]
  double max_tolerance = 0.05;          // [-a batch tol]
  int adaptive_budget = 0;              // [--adaptive-budget spp] mean samples per pixel, allocated by
                                        // render/budget.h; 0: off
  int adaptive_rounds = 4;              // [--adaptive-rounds K] the budget's rounds after the pilot, r
                                        // re-estimated before each (1: exactly unbiased, budget.h)
  uint64_t seed = 0;                    // render seed; every pixel's stream derives from it
};

}  // namespace pt
