#pragma once
// The viewer's render: progressive passes over the whole image or one cell,
// on a control thread of its own, that the HTTP handlers steer (restart,
// pause, stop) and read (status, a snapshot of the image). One render at a
// time: a restart cancels the running pass before the next one starts.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/image.h"
#include "render/pathtracer.h"
#include "scene/scene.h"

namespace pt {

// The view the page steers; the camera file (-c) holds exactly these fields.
struct ViewState {
  Vec3 position{0.0}, target{0.0, 0.0, -1.0}, up{0.0, 1.0, 0.0};
  double vfov = 35.0, near_clip = 1e-4, far_clip = 1e30;
  // The camera a render at width x height uses, built as `-c` builds it.
  Camera camera(int width, int height) const;
};
// The view of a loaded camera, pivoting at the depth of `pivot`.
ViewState view_of(const Camera& camera, const Vec3& pivot);

// Makes the estimator a render uses: the plain PathTracer, or a test's stand-in.
using TracerFactory = std::function<std::unique_ptr<PathTracer>(const Scene&, const RenderSettings&)>;

// A rectangle of pixels [x0, x1) x [y0, y1), rows counted from the top.
struct Cell {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

struct SessionStatus {
  std::string state;  // rendering, paused, done, stopped, error
  std::string error;  // a task's exception, as thrown ("not implemented: P1T3 ...")
  double spp = 0;     // mean samples per pixel so far in the rendered region
  int target_spp = 0;
  double rays_per_second = 0, eta_seconds = 0, seconds = 0;
  uint64_t generation = 0;  // changes whenever the image is reset
  uint64_t version = 0;     // changes whenever the image changes
  Cell cell;                // the region being rendered
};

// The mean image so far and samples per pixel (row 0 at the top).
struct Snapshot {
  Image image;
  std::vector<int> samples;
};

class RenderSession {
 public:
  // The session sets scene.camera to the view before each render (a task may
  // read the camera from the scene), and reads the scene otherwise.
  RenderSession(Scene& scene, int threads, TracerFactory make_tracer);
  ~RenderSession();  // cancels the render and joins its threads

  // Clears the image and renders `view` with `settings` from pass 0. A
  // non-empty cell renders only those pixels and keeps the rest of the image.
  void restart(const RenderSettings& settings, const ViewState& view, const Cell& cell = {});
  void set_paused(bool paused);
  void stop();  // ends the render, keeps the image

  SessionStatus status() const;
  Snapshot snapshot() const;
  RenderSettings settings() const;
  ViewState view() const;

  // Samples per pass: each pass draws this many per pixel from
  // Rng::for_pixel(seed, x, y, pass), so the first pass of a render with
  // -s <= kPassSamples is exactly the headless render with the same flags.
  static constexpr int kPassSamples = 4;

 private:
  void control_loop();
  void render_run(uint64_t generation);
  bool cancelled(uint64_t generation) const;

  Scene& scene_;
  const int threads_;
  TracerFactory make_tracer_;

  mutable std::mutex mutex_;  // guards everything below
  std::condition_variable wake_;
  bool quit_ = false, paused_ = false, running_ = false, stopped_ = false;
  uint64_t generation_ = 0, rendered_generation_ = 0, version_ = 0;
  RenderSettings settings_;
  ViewState view_;
  Cell cell_;
  std::vector<Spectrum> sum_;  // radiance summed over samples, row 0 at the top
  std::vector<int> samples_;
  std::string error_;
  double active_seconds_ = 0;  // time spent rendering this generation, pauses excluded
  uint64_t rays_ = 0;
  std::chrono::steady_clock::time_point active_since_;
  std::thread control_;
};

}  // namespace pt
