#include "verifier_link.h"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <random>
#include <utility>
#include <vector>

#include "crossing.h"
#include "generator_calls.h"
#include "one_cpu.h"
#include "process/launcher.h"
#include "scene_codec.h"

namespace pt::boundary {
namespace {

std::vector<std::string> own_arguments() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> args;
  for (std::string a; std::getline(in, a, '\0');) args.push_back(a);
  return args;
}

[[noreturn]] void worker_lost(const std::string& why, int status = kWorkerLost) {
  std::fflush(stdout);
  std::fprintf(stderr, "\n[  WORKER  ] the link to the process running the task's code ended (%s); this test has no "
               "verdict\n", why.c_str());
  std::fflush(stderr);
  std::_Exit(status);
}

// This process, and so the worker it starts, on one CPU (one_cpu.h): the
// threads there are now, and those started later (the worker's spawner, a
// renderer's pool), which inherit it.
void share_one_cpu() {
  const std::optional<cpu_set_t> one = one_cpu();
  if (!one) return;
  std::error_code error;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", error)) {
    const pid_t tid = static_cast<pid_t>(std::atoi(task.path().filename().c_str()));
    if (tid > 0) ::sched_setaffinity(tid, sizeof *one, &*one);
  }
  ::sched_setaffinity(0, sizeof *one, &*one);
}

// Starts the worker with the requests on its descriptor 4 and its answers on 3.
void start_worker(const std::string& path, int& in, int& out) {
  // Said here: an exec that fails in the child reads as a worker that never started.
  if (::access(path.c_str(), X_OK) != 0) worker_lost("could not start " + path + ": " + std::strerror(errno));
  share_one_cpu();
  int requests[2], answers[2];
  if (::pipe2(requests, O_CLOEXEC) != 0 || ::pipe2(answers, O_CLOEXEC) != 0) worker_lost("pipe failed");
  // Above 4 first, so that placing one end at 3 or 4 never overwrites another.
  for (int* fd : {&requests[0], &requests[1], &answers[0], &answers[1]}) {
    const int high = ::fcntl(*fd, F_DUPFD_CLOEXEC, 10);
    ::close(*fd);
    *fd = high;
  }
  // The worker dies with the thread that started it (PR_SET_PDEATHSIG), so a
  // thread that lives as long as this process starts it, whichever thread
  // asks first: a renderer's pool thread ends with its render.
  auto spawned = std::make_shared<std::promise<int>>();
  std::future<int> result = spawned->get_future();
  std::thread([spawned, &path, &requests, &answers] {
    char* argv[] = {const_cast<char*>(path.c_str()), nullptr};
    grade::LaunchOptions launch;
    launch.child_ends = {answers[1], requests[0]};
    // Only what is async-signal-safe runs in the copy of this threaded process.
    grade::Child worker(launch, [&] {
      if (::dup2(answers[1], 3) == 3 && ::dup2(requests[0], 4) == 4) {
        ::close_range(5, ~0u, 0);
        ::execv(argv[0], argv);
      }
    });
    spawned->set_value(worker.started() ? 0 : worker.start_error());
    for (;;) ::pause();
  }).detach();
  const int err = result.get();
  if (err != 0) worker_lost("could not start " + path + ": " + std::strerror(err));
  in = answers[0];
  out = requests[1];
}

std::vector<std::pair<Call, Handler>>& callbacks() {
  static std::vector<std::pair<Call, Handler>> all;
  return all;
}

// Each callback is served through the tape of a call being replayed, if any
// (generator_calls.h): a replay must make the callbacks the first time made.
void serve_callbacks(Link& link) {
  for (const auto& [call, handler] : callbacks())
    link.on(call, [call = call, handler = handler](Reader& args, Writer& result) {
      Reader received(args.all());
      args.skip_to_end();  // read by `received`, unless the tape answers
      through_tape(call, received.all(), result, [&](Writer& answer) {
        handler(received, answer);
        received.finish();
      });
    });
}

// A pixel's samples (PixelTracer): the radiance of the tracer the test made.
void est_radiance(Reader& args, Writer& result) {
  if (!g_tracer) throw std::runtime_error("est_radiance_global_illumination called outside a pixel's sampling");
  const Ray ray = Crossing<Ray>::get(args);
  auto rng = args.get<Rng>();
  result.put(g_tracer->est_radiance_global_illumination(ray, rng)).put(rng);
}

// sample_adaptively's samples (CALLBACK): the test's next_sample.
void next_sample(Reader&, Writer& result) {
  if (!g_next_sample) throw std::runtime_error("next_sample called outside sample_adaptively");
  result.put((*g_next_sample)());
}

const bool kCallbacksServed = (serve_callback(Call::EstRadiance, est_radiance),
                               serve_callback(Call::NextSample, next_sample), true);

Link* make_link() {
  // Nothing of this process may be read through /proc by a process of the
  // same user (the worker, when no PID namespace keeps it from seeing this one).
  ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
  // A worker that died is seen as a failed write (EPIPE), not as a signal
  // that would end this process without saying so.
  ::signal(SIGPIPE, SIG_IGN);
  int in = -1, out = -1;
  for (const std::string& a : own_arguments()) {
    char extra;
    if (std::sscanf(a.c_str(), "--pt_worker_fds=%d,%d%c", &in, &out, &extra) == 2) break;
    if (a.rfind("--pt_worker=", 0) == 0) {
      start_worker(a.substr(12), in, out);
      break;
    }
  }
  if (in < 0 || out < 0) return nullptr;
  auto* link = new Link(in, out);
  try {
    link->await_hello();
  } catch (const LinkClosed& e) {
    worker_lost(e.what(), kWorkerNeverStarted);
  } catch (const LinkBroken& e) {
    worker_lost(e.what(), kWorkerBrokeLink);
  }
  serve_callbacks(*link);
  return link;
}

std::recursive_mutex& link_mutex() {
  static std::recursive_mutex m;
  return m;
}

}  // namespace

std::string call_worker(Call call, const Writer& args) {
  std::lock_guard<std::recursive_mutex> lock(link_mutex());
  static Link* const link = make_link();
  if (!link)
    throw std::runtime_error(
        "this test binary runs the task's code in a worker process and was given none: run it with "
        "--pt_worker=PATH (e.g. part1_worker), or through pt-grade");
  try {
    return link->call(call, args);
  } catch (const LinkClosed& e) {
    worker_lost(e.what());
  } catch (const LinkBroken& e) {
    worker_lost(e.what(), kWorkerBrokeLink);
  }
}

void serve_callback(Call call, Handler handler) { callbacks().emplace_back(call, std::move(handler)); }

void answer_broke_link(const std::string& why) { worker_lost(why, kWorkerBrokeLink); }

std::unique_lock<std::recursive_mutex> hold_link() { return std::unique_lock<std::recursive_mutex>(link_mutex()); }

SceneRef refer_to(const Scene& scene) {
  std::lock_guard<std::recursive_mutex> lock(link_mutex());
  static const Scene* sent = nullptr;
  static uint64_t sent_revision = 0, id = 0;
  static SceneIndex index;
  if (&scene != sent || scene.revision() != sent_revision) {
    Writer definition;
    SceneIndex new_index;
    definition.put(id + 1);
    put_scene(definition, scene, new_index);
    sent = nullptr;  // the worker's scene is unknown until it answers
    const std::string answer = call_worker(Call::DefineScene, definition);
    read_answer([&] {
      Reader(answer).finish();  // nothing comes back
      return 0;
    });
    index = std::move(new_index);
    sent = &scene;
    sent_revision = scene.revision();
    ++id;
  }
  return {id, index};
}

}  // namespace pt::boundary
