#pragma once
// The verifier's end of the boundary (README.md beside this file): the graded
// tests call the proxies of one part's task functions (proxies.cpp), and each
// proxy asks the worker, where the student's code runs, over the link made
// here.
//
// The link comes from the command line, on first use:
//   --pt_worker_fds=IN,OUT  the worker is already running (pt-grade started it
//                           in the sandbox, on pipes at these descriptors)
//   --pt_worker=PATH        start PATH here (a student's or ctest's run)
// Without either, every proxy fails its test saying so.
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

#include "render/pathtracer.h"
#include "scene/scene.h"
#include "scoped.h"
#include "verifier_exit_codes.h"
#include "wire.h"

namespace pt::boundary {

// Calls the worker (one call at a time, from any thread). A broken link ends
// this process with kWorkerLost after saying why on stderr.
std::string call_worker(Call call, const Writer& args);

// A callback into the verifier (a codec's: Part 2's primitive tests), served
// from the first call on, from its tape while a call is replayed
// (generator_calls.h). Call before the first call (a static initializer).
void serve_callback(Call call, Handler handler);

// Keeps other threads off the link for a sequence of calls that belong
// together (a scene's definition and the calls that name it).
std::unique_lock<std::recursive_mutex> hold_link();

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

// Where the worker's calls back go, while a call that makes them is answered
// (Scoped): EstRadiance to this tracer's est_radiance_global_illumination (a
// test's scripted one, or the solution's), NextSample to Part 5's next_sample.
inline thread_local const PathTracer* g_tracer = nullptr;
inline thread_local const std::function<Spectrum()>* g_next_sample = nullptr;

}  // namespace pt::boundary
