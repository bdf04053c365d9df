#include "app/viewer_session.h"

#include <algorithm>
#include <exception>

#include "core/stats.h"
#include "render/limits.h"
#include "render/worker_threads.h"

namespace pt {

namespace {
constexpr int kTile = 16;
using Clock = std::chrono::steady_clock;
double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }
}  // namespace

Camera ViewState::camera(int width, int height) const {
  // As io/scene_loader.cpp's read_camera and the command line do with -c.
  Camera c(position, target, up, vfov, vfov, near_clip, far_clip);
  c.set_aspect(double(width) / height);
  return c;
}

ViewState view_of(const Camera& camera, const Vec3& pivot) {
  ViewState v;
  v.position = camera.pos;
  const Vec3 forward = -camera.c2w[2];
  double depth = glm::dot(pivot - camera.pos, forward);
  if (!(depth > 1e-6)) depth = std::max(glm::length(pivot - camera.pos), 1.0);
  v.target = camera.pos + depth * forward;
  v.up = camera.c2w[1];
  v.vfov = camera.vfov;
  v.near_clip = camera.near_clip;
  v.far_clip = camera.far_clip;
  return v;
}

RenderSession::RenderSession(Scene& scene, int threads, TracerFactory make_tracer)
    : scene_(scene), threads_(threads), make_tracer_(std::move(make_tracer)) {
  control_ = std::thread([this] { control_loop(); });
}

RenderSession::~RenderSession() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  control_.join();
}

void RenderSession::restart(const RenderSettings& settings, const ViewState& view, const Cell& cell) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const size_t n = size_t(settings.width) * settings.height;
    const bool same_size = settings_.width == settings.width && settings_.height == settings.height && sum_.size() == n;
    settings_ = settings;
    view_ = view;
    Cell c{std::max(cell.x0, 0), std::max(cell.y0, 0), std::min(cell.x1, settings.width),
           std::min(cell.y1, settings.height)};
    if (cell.empty() || c.empty() || !same_size) {
      sum_.assign(n, Spectrum(0.0));
      samples_.assign(n, 0);
      c = Cell{0, 0, settings.width, settings.height};
    } else {
      for (int row = c.y0; row < c.y1; ++row)
        for (int x = c.x0; x < c.x1; ++x) {
          sum_[size_t(row) * settings.width + x] = Spectrum(0.0);
          samples_[size_t(row) * settings.width + x] = 0;
        }
    }
    cell_ = c;
    error_.clear();
    stopped_ = paused_ = false;
    ++generation_;
    ++version_;
    active_seconds_ = 0;
    rays_ = 0;
    active_since_ = Clock::now();
  }
  wake_.notify_all();
}

void RenderSession::set_paused(bool paused) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (paused == paused_) return;
    const auto now = Clock::now();
    if (paused && running_) active_seconds_ += seconds_between(active_since_, now);
    active_since_ = now;
    paused_ = paused;
  }
  wake_.notify_all();
}

void RenderSession::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    paused_ = false;
  }
  wake_.notify_all();
}

bool RenderSession::cancelled(uint64_t generation) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return quit_ || stopped_ || generation != generation_;
}

void RenderSession::control_loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    wake_.wait(lock, [&] { return quit_ || generation_ != rendered_generation_; });
    if (quit_) return;
    const uint64_t generation = generation_;
    rendered_generation_ = generation;
    running_ = true;
    active_since_ = Clock::now();
    lock.unlock();
    render_run(generation);
    lock.lock();
    if (generation == generation_ && !paused_) active_seconds_ += seconds_between(active_since_, Clock::now());
    running_ = false;
  }
}

void RenderSession::render_run(uint64_t generation) {
  RenderSettings s;
  Cell cell;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    s = settings_;
    cell = cell_;
    // Only this thread renders, so the scene's camera is free to change here.
    scene_.camera = view_.camera(s.width, s.height);
  }
  auto fail = [&](const std::string& what) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (generation == generation_) error_ = what;
  };
  std::unique_ptr<PathTracer> tracer;
  try {
    tracer = make_tracer_(scene_, s);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  const int tiles_x = (cell.x1 - cell.x0 + kTile - 1) / kTile, tiles_y = (cell.y1 - cell.y0 + kTile - 1) / kTile;
  const int passes = s.adaptive ? 1 : (s.ns_aa + kPassSamples - 1) / kPassSamples;
  for (int pass = 0; pass < passes && !cancelled(generation); ++pass) {
    // Adaptive sampling needs all of a pixel's samples at once: one pass.
    tracer->settings.ns_aa = s.adaptive ? s.ns_aa : std::min(kPassSamples, s.ns_aa - pass * kPassSamples);
    std::atomic<int> next_tile{0};
    std::atomic<bool> failed{false};
    auto worker = [&] {
      take_work_counters();
      std::vector<PixelEstimate> tile(size_t(kTile) * kTile);
      try {
        for (int t; !failed && (t = next_tile++) < tiles_x * tiles_y;) {
          {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return !paused_ || quit_ || stopped_ || generation != generation_; });
            if (quit_ || stopped_ || generation != generation_) return;
          }
          const int x0 = cell.x0 + (t % tiles_x) * kTile, row0 = cell.y0 + (t / tiles_x) * kTile;
          const int x1 = std::min(x0 + kTile, cell.x1), row1 = std::min(row0 + kTile, cell.y1);
          for (int row = row0; row < row1; ++row)
            for (int x = x0; x < x1; ++x) {
              const int y = s.height - 1 - row;  // the tasks count pixel rows from the bottom
              Rng rng = Rng::for_pixel(s.seed, x, y, uint32_t(pass));
              tile[size_t(row - row0) * kTile + (x - x0)] =
                  s.adaptive ? tracer->raytrace_pixel_adaptive(x, y, rng) : tracer->raytrace_pixel(x, y, rng);
            }
          std::lock_guard<std::mutex> lock(mutex_);
          if (generation != generation_) return;
          for (int row = row0; row < row1; ++row)
            for (int x = x0; x < x1; ++x) {
              const PixelEstimate& p = tile[size_t(row - row0) * kTile + (x - x0)];
              const size_t i = size_t(row) * s.width + x;
              // NaN or infinite estimates count their samples but add nothing,
              // as the headless renderer writes them black.
              if (is_finite(p.radiance)) sum_[i] += p.radiance * double(p.num_samples);
              samples_[i] += p.num_samples;
            }
          ++version_;
          rays_ += take_work_counters().rays;
        }
      } catch (const std::exception& e) {
        failed = true;
        fail(e.what());
      } catch (...) {
        failed = true;
        fail("unknown exception");
      }
    };
    std::string why;
    if (run_on_threads(threads_, kRenderThreadStackBytes, worker, &why) == 0) return fail(why);
    if (failed) return;
  }
}

SessionStatus RenderSession::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  SessionStatus st;
  const bool busy = running_ || generation_ != rendered_generation_;
  st.state = !error_.empty() ? "error" : stopped_ ? "stopped" : paused_ && busy ? "paused" : busy ? "rendering" : "done";
  st.error = error_;
  st.cell = cell_;
  st.target_spp = settings_.ns_aa;
  long long total = 0;
  for (int row = cell_.y0; row < cell_.y1; ++row)
    for (int x = cell_.x0; x < cell_.x1; ++x) total += samples_[size_t(row) * settings_.width + x];
  const double pixels = double(cell_.x1 - cell_.x0) * (cell_.y1 - cell_.y0);
  st.spp = pixels > 0 ? total / pixels : 0;
  st.seconds = active_seconds_ + (running_ && !paused_ ? seconds_between(active_since_, Clock::now()) : 0.0);
  st.rays_per_second = st.seconds > 0 ? rays_ / st.seconds : 0;
  const double done = st.target_spp > 0 ? std::min(st.spp / st.target_spp, 1.0) : 1.0;
  st.eta_seconds = st.state == "rendering" && done > 0 ? st.seconds * (1 - done) / done : 0;
  st.generation = generation_;
  st.version = version_;
  return st;
}

Snapshot RenderSession::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  Snapshot snap{Image(settings_.width, settings_.height), samples_};
  for (size_t i = 0; i < sum_.size(); ++i)
    if (samples_[i] > 0) snap.image.pixels[i] = sum_[i] / double(samples_[i]);
  return snap;
}

RenderSettings RenderSession::settings() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return settings_;
}

ViewState RenderSession::view() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return view_;
}

}  // namespace pt
