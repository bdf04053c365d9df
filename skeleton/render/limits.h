#pragma once
// Bounds on what a render may ask for. The command line refuses values beyond
// them with the bound in its message (README.md lists them), and render()
// refuses them too, so that no caller can overflow an index, exhaust the
// memory or the stack, or start a render that could never finish, by asking.
#include <cstddef>
#include <string>

#include "render/settings.h"

namespace pt {

// Image size. A render holds about 40 bytes per pixel at its peak (radiance
// as three doubles, the sample counts, the PNG and EXR encodings while
// writing: 663 MB measured at 4096 x 4096, tests/cli/README.md), so 2^25
// pixels (8K UHD, 7680 x 4320, fits) is about 1.3 GB. Either side alone may
// reach 16384 (panoramas).
constexpr int kMaxImageSide = 16384;
constexpr long long kMaxPixels = 1LL << 25;

// Samples per pixel and per area light. Beyond these a render runs for days:
// a larger value is a typo. Their product stays below 2^31, so code that
// multiplies the two in an int does not overflow.
constexpr int kMaxSamples = 1 << 20;
constexpr int kMaxLightSamples = 1 << 10;

// The budgeted sampler's pilot estimates a variance: two samples at least.
constexpr int kMinAdaptiveBudget = 2;
constexpr int kMaxAdaptiveRounds = 16;  // more rounds than this re-estimate from a handful of samples each

// Ray depth. The path estimator recurses once per bounce (the assignment's
// design), so its depth is bounded by the stack. Measured in the closed box
// with --rr 1 (every path runs to the maximum depth): the reference takes 545
// bytes of stack per bounce at -O2, 731 at -O0 and 1,356 at -O0 under
// AddressSanitizer (tests/cli/README.md). Render threads get
// kRenderThreadStackBytes, so the deepest allowed path has 6.5 KiB per bounce:
// about 5 times the heaviest measured frame, room for a student's recursion
// with more locals. No image needs more: at albedo 0.99 the 10,000th bounce
// carries 2e-44 of the light.
constexpr int kMaxRayDepth = 10000;
constexpr size_t kRenderThreadStackBytes = size_t(64) << 20;

// Render threads: more than the cores only queue; the bound catches typos
// before the system refuses the threads (and their 64 MiB stacks).
constexpr int kMaxThreads = 1024;

// "" when the settings are within the bounds above; else what is wrong, with
// the bound.
std::string check_render_limits(const RenderSettings& s, int threads);

}  // namespace pt
