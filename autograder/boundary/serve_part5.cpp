// The worker's Part 5: the verifier's calls (proxies_part5.cpp) answered by
// the student's task functions; the samples they draw come from the verifier.
#include "remote_tracer.h"

namespace pt::boundary {

void serve_task_calls(Link& link) {
  link.on(Call::SampleAdaptively, [&link](Reader& in, Writer& out) {
    const auto max_samples = in.get<int>(), samples_per_batch = in.get<int>();
    const auto max_tolerance = in.get<double>();
    const std::function<Spectrum()> next_sample = [&link] {
      const std::string answer = link.call(Call::NextSample, Writer());
      Reader sample(answer);
      const auto value = sample.get<Spectrum>();
      sample.finish();
      return value;
    };
    out.put(sample_adaptively(next_sample, max_samples, samples_per_batch, max_tolerance));
  });
  link.on(Call::RaytracePixelAdaptive, [&link](Reader& in, Writer& out) {
    serve_pixel(link, in, out, &PathTracer::raytrace_pixel_adaptive);
  });
  link.on(Call::AllocateSamples, [](Reader& in, Writer& out) {
    const auto pilot = in.get_vector<PilotMoments>(kMaxPayload / sizeof(PilotMoments));
    const auto budget = in.get<long long>();
    out.put_vector(allocate_samples(pilot, budget));
  });
}

}  // namespace pt::boundary
