#pragma once
// The verifier's end of the boundary (README.md beside this file): the graded
// tests call the proxies of one part's task functions, and each proxy asks the
// worker, where the student's code runs, over the link made here.
//
// The link comes from the command line, on first use:
//   --pt_worker_fds=IN,OUT  the worker is already running (pt-grade started it
//                           in the sandbox, on pipes at these descriptors)
//   --pt_worker=PATH        start PATH here (a student's or ctest's run)
// Without either, every proxy fails its test saying so.
#include <cstdint>
#include <mutex>
#include <string>

#include "render/pathtracer.h"
#include "scene_codec.h"
#include "verifier_exit_codes.h"
#include "wire.h"

namespace pt::boundary {

// Calls the worker (one call at a time, from any thread). A broken link ends
// this process with kWorkerLost after saying why on stderr.
std::string call_worker(Call call, const Writer& args);

// A callback of one part (Part 2's primitive tests), served from the first
// call on. Call before the first call (a static initializer of the part's
// proxies).
void serve_callback(Call call, Handler handler);

// Keeps other threads off the link for a sequence of calls that belong
// together (a scene's definition and the calls that name it).
std::unique_lock<std::recursive_mutex> hold_link();

// The id under which the worker keeps `scene`, sent now unless it is the
// scene sent last (the same object, unchanged since: Scene::revision), and
// the index of its objects. Call with the link held until the calls that
// name it are made.
struct SceneRef {
  uint64_t id;
  const SceneIndex& index;
};
SceneRef refer_to(const Scene& scene);

// Runs `read`, which reads an answer of the worker: an answer that does not
// read as its call's values (too short, too long, a run longer than asked
// for) breaks the link as a malformed message does, and this process ends
// with kWorkerBrokeLink.
[[noreturn]] void answer_broke_link(const std::string& why);
template <class Read>
auto read_answer(Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const LinkBroken& e) {
    answer_broke_link(e.what());
  }
}

// A pixel's sampling (P1T2's raytrace_pixel, P5T1's adaptive one) in the
// worker: the settings, camera, pixel and generator go, the estimate and the
// generator's state come back, and the radiance of each sample is `tracer`'s.
// The state must be the one sent moved forward, and a share of the calls is
// replayed, their callbacks answered as the first time, and must give the same
// answer (support/generator_contract.h); `task` names the function if not.
PixelEstimate ask_pixel(Call call, const std::string& task, const PathTracer& tracer, int x, int y, Rng& rng);

// While one lives, the worker's calls back to EstRadiance go to `tracer`
// (its own est_radiance_global_illumination: a test's scripted one, or the
// solution's).
class TracerScope {
 public:
  explicit TracerScope(const PathTracer* tracer);
  ~TracerScope();
  TracerScope(const TracerScope&) = delete;
  TracerScope& operator=(const TracerScope&) = delete;

 private:
  const PathTracer* previous_;
};

// The same for Part 5's next_sample.
class SampleSourceScope {
 public:
  explicit SampleSourceScope(const std::function<Spectrum()>* next_sample);
  ~SampleSourceScope();
  SampleSourceScope(const SampleSourceScope&) = delete;
  SampleSourceScope& operator=(const SampleSourceScope&) = delete;

 private:
  const std::function<Spectrum()>* previous_;
};

}  // namespace pt::boundary
