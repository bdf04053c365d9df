// The verifier's Part 5: each task function asks the worker (README.md beside
// this file). Each sample a test hands out (next_sample, the tracer's
// radiance) is asked for from the worker's side, one call at a time.
#include "render/pathtracer.h"
#include "verifier_link.h"

namespace pt {

using boundary::Call;
using boundary::call_worker;
using boundary::Reader;
using boundary::Writer;

PixelEstimate sample_adaptively(const std::function<Spectrum()>& next_sample, int max_samples, int samples_per_batch,
                                double max_tolerance) {
  boundary::SampleSourceScope scope(&next_sample);
  Writer in;
  in.put(max_samples).put(samples_per_batch).put(max_tolerance);
  const std::string answer = call_worker(Call::SampleAdaptively, in);
  return boundary::read_answer([&] {
    Reader out(answer);
    const auto estimate = out.get<PixelEstimate>();
    out.finish();
    return estimate;
  });
}

PixelEstimate PathTracer::raytrace_pixel_adaptive(int x, int y, Rng& rng) const {
  return boundary::ask_pixel(Call::RaytracePixelAdaptive, "PathTracer::raytrace_pixel_adaptive", *this, x, y, rng);
}

std::vector<int> allocate_samples(const std::vector<PilotMoments>& pilot, long long budget) {
  Writer in;
  in.put_vector(pilot).put(budget);
  const std::string answer = call_worker(Call::AllocateSamples, in);
  return boundary::read_answer([&] {
    Reader out(answer);
    // Any length the message can hold: a wrong one is for the tests to see.
    auto counts = out.get_vector<int>(boundary::kMaxPayload / sizeof(int));
    out.finish();
    return counts;
  });
}

}  // namespace pt
