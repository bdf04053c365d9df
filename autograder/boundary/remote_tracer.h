#pragma once
// The worker's stand-in for the verifier's PathTracer: the student's code
// (raytrace_pixel, raytrace_pixel_adaptive) calls est_radiance_global_illumination,
// and the verifier's own tracer answers, be it a test's script or the solution.
#include "render/pathtracer.h"
#include "scene/scene.h"
#include "wire.h"

namespace pt::boundary {

class RemoteTracer : public PathTracer {
 public:
  RemoteTracer(const Scene& scene, const RenderSettings& settings, Link& link) : PathTracer(scene, settings), link_(link) {}

  Spectrum est_radiance_global_illumination(const Ray& r, Rng& rng) const override {
    Writer args;
    args.put(r).put(rng);
    const std::string answer = link_.call(Call::EstRadiance, args);
    Reader result(answer);
    const auto radiance = result.get<Spectrum>();
    result.get(rng);
    result.finish();
    return radiance;
  }

 private:
  Link& link_;
};

// Serves a pixel's sampling (verifier_link.h, ask_pixel) with the student's
// `sample_pixel` (&PathTracer::raytrace_pixel or raytrace_pixel_adaptive).
inline void serve_pixel(Link& link, Reader& in, Writer& out,
                        PixelEstimate (PathTracer::*sample_pixel)(int, int, Rng&) const) {
  const auto settings = in.get<RenderSettings>();
  Scene scene;
  in.get(scene.camera);
  const auto x = in.get<int>(), y = in.get<int>();
  auto rng = in.get<Rng>();
  const RemoteTracer tracer(scene, settings, link);
  out.put((tracer.*sample_pixel)(x, y, rng)).put(rng);
}

}  // namespace pt::boundary
