#include "app/viewer_server.h"

#include <pthread.h>
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <httplib.h>

#include "app/part_origins.h"
#include "app/viewer_entry.h"
#include "app/viewer_inspect.h"
#include "app/viewer_library.h"
#include "app/viewer_page.h"
#include "scene/course_camera.h"

namespace pt {

using json = nlohmann::json;

namespace {

void send_json(httplib::Response& res, const json& j, int status = 200) {
  res.status = status;
  res.set_content(j.dump(), "application/json");
}
void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, {{"error", message}}, status);
}

json parse_body(const httplib::Request& req) {
  try {
    return json::parse(req.body);
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("the request body is not JSON: ") + e.what());
  }
}

// A query parameter as an integer in [lo, hi); throws std::invalid_argument.
int int_param(const httplib::Request& req, const char* name, int lo, int hi) {
  if (!req.has_param(name)) throw std::invalid_argument(std::string("missing parameter ") + name);
  const std::string text = req.get_param_value(name);
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < lo || v >= hi)
    throw std::invalid_argument(std::string(name) + "=" + text + " is not an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + ")");
  return int(v);
}

double srgb_encode(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

// RGBA bytes of the image as write_png encodes it (exposure in stops, sRGB).
std::string rgba_bytes(const Image& image, double exposure) {
  const double scale = std::exp2(exposure);
  std::string out(image.pixels.size() * 4, '\xff');
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double v = image.pixels[i][c] * scale;
      v = std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
      out[4 * i + c] = char(std::lround(255.0 * srgb_encode(v)));
    }
  return out;
}

void send_image(httplib::Response& res, const Image& image, double exposure) {
  res.set_header("X-Width", std::to_string(image.width));
  res.set_header("X-Height", std::to_string(image.height));
  res.set_content(rgba_bytes(image, exposure), "application/octet-stream");
}

}  // namespace

struct ViewerServer::Impl {
  Scene& scene;
  ViewerOptions options;
  const Camera loaded_camera;  // the scene's camera (the session changes scene.camera)
  httplib::Server http;
  int port = -1;
  std::atomic<bool> serving{false}, stopped{false};
  ViewState scene_view, course_view;
  RenderSession session;
  std::mutex mutex;  // guards settings and the library reference
  ViewerSettings settings;
  bool library_loaded = false;
  std::optional<LibraryReference> library;
  std::string library_error;

  Impl(Scene& s, ViewerOptions o)
      : scene(s),
        options(std::move(o)),
        loaded_camera(s.camera),
        session(s, options.threads, [this](const Scene& sc, const RenderSettings& rs) { return make_tracer(sc, rs); }),
        settings(options.settings) {
    const BBox bounds = scene.bounds();
    scene_view = view_of(loaded_camera, bounds.centroid());
    const RenderSettings& r = settings.render;
    course_view = view_of(course_camera(loaded_camera, bounds, r.width, r.height), bounds.centroid());
    routes();
  }

  // The estimator a render or the inspector uses; none without a BVH.
  std::unique_ptr<PathTracer> make_tracer(const Scene& sc, const RenderSettings& rs) const {
    if (!options.scene_error.empty() || !sc.bvh) throw std::runtime_error(options.scene_error.empty() ? "the scene has no BVH" : options.scene_error);
    return options.make_tracer ? options.make_tracer(sc, rs) : std::make_unique<PathTracer>(sc, rs);
  }

  std::vector<std::string> allowed_hosts() const {
    return {"127.0.0.1:" + std::to_string(port), "localhost:" + std::to_string(port)};
  }

  // The Host header must name this server (a page from another site that
  // rebinds its name to 127.0.0.1 sends its own name); a change must not come
  // from another origin's page.
  httplib::Server::HandlerResponse check_origin(const httplib::Request& req, httplib::Response& res) const {
    const auto hosts = allowed_hosts();
    const std::string host = req.get_header_value("Host");
    if (std::find(hosts.begin(), hosts.end(), host) == hosts.end()) {
      send_error(res, 403, "Host '" + host + "' is not this viewer (" + hosts[0] + "): refused");
      return httplib::Server::HandlerResponse::Handled;
    }
    if (req.has_header("Origin")) {
      const std::string origin = req.get_header_value("Origin");
      if (origin != "http://" + hosts[0] && origin != "http://" + hosts[1]) {
        send_error(res, 403, "Origin '" + origin + "' is not this viewer's page: refused");
        return httplib::Server::HandlerResponse::Handled;
      }
    }
    return httplib::Server::HandlerResponse::Unhandled;
  }

  void restart(const Cell& cell = {}) {
    session.restart(settings.render, session_view(), cell);
  }
  ViewState session_view() const { return current_view; }
  ViewState current_view;

  json status_json() {
    const SessionStatus st = session.status();
    std::lock_guard<std::mutex> lock(mutex);
    return {{"state", st.state},
            {"error", st.error},
            {"hint", stub_hint(st.error)},  // the option that lets the solution stand in
            {"spp", st.spp},
            {"target_spp", st.target_spp},
            {"rays_per_second", st.rays_per_second},
            {"eta_seconds", st.eta_seconds},
            {"seconds", st.seconds},
            {"generation", st.generation},
            {"version", st.version},
            {"cell", {st.cell.x0, st.cell.y0, st.cell.x1, st.cell.y1}},
            {"settings", settings_json(settings)},
            {"camera", camera_json(session.view())},
            {"scene", options.scene_path},
            {"threads", options.threads},
            {"primitives", scene.primitives.size()},
            {"pass_samples", RenderSession::kPassSamples}};
  }

  const LibraryReference* library_reference() {
    if (!library_loaded) {
      library_loaded = true;
      try {
        library = find_library_reference(options.scene_path);
      } catch (const std::exception& e) {
        library_error = e.what();
      }
    }
    return library ? &*library : nullptr;
  }

  json compare_json() {
    std::lock_guard<std::mutex> lock(mutex);
    const LibraryReference* ref = library_reference();
    if (!ref) return {{"available", false}, {"reason", library_error.empty() ? "this scene is not in the scene library (scenes/library.json)" : library_error}};
    json j{{"available", true}, {"name", ref->name}, {"reference_samples", ref->model.reference_samples},
           {"library_settings", {{"width", ref->settings.width}, {"height", ref->settings.height},
                                 {"light_samples", ref->settings.ns_area_light}, {"max_depth", ref->settings.max_ray_depth},
                                 {"rr", ref->settings.rr_continue_prob}}}};
    const RenderSettings& s = settings.render;
    json differs = json::array();
    if (s.width != ref->settings.width || s.height != ref->settings.height) differs.push_back("resolution");
    if (s.max_ray_depth != ref->settings.max_ray_depth) differs.push_back("max depth");
    if (s.ns_area_light != ref->settings.ns_area_light) differs.push_back("light samples");
    if (s.rr_continue_prob != ref->settings.rr_continue_prob) differs.push_back("rr");
    if (s.direct_hemisphere_sample) differs.push_back("-H");
    if (!s.accumulate_bounces) differs.push_back("-o 0");
    if (s.adaptive) differs.push_back("-a");
    const ViewState v = session.view();
    if (v.position != scene_view.position || v.target != scene_view.target || v.up != scene_view.up || v.vfov != scene_view.vfov)
      differs.push_back("camera");
    j["differs"] = differs;
    if (s.width != ref->settings.width || s.height != ref->settings.height) return j;
    const Snapshot snap = session.snapshot();
    const SessionStatus st = session.status();
    const ImageError e = compare_images(snap.image, ref->image);
    j["relmse"] = e.relmse;
    j["rmse"] = e.rmse;
    j["spp"] = st.spp;
    if (st.spp > 0) {
      j["expected_relmse"] = ref->model.expected(st.spp);
      j["sd_relmse"] = ref->model.sd(st.spp);
      j["bound_relmse"] = ref->model.bound(st.spp, kLibraryCheckZ);
    }
    return j;
  }

  // The server's endpoints, by what they serve.
  void routes() {
    guard_requests();
    page_routes();
    image_routes();
    control_routes();
    camera_routes();
    inspect_routes();
    compare_routes();
  }
  void guard_requests();
  void page_routes();
  void image_routes();
  void control_routes();
  void camera_routes();
  void inspect_routes();
  void compare_routes();
  void send_image_of(const std::string& kind, httplib::Response& res);
};

// Where requests may come from, how large they may be, and how an error or an
// exception becomes a response.
void ViewerServer::Impl::guard_requests() {
  // httplib's default also sets SO_REUSEPORT, which lets a second viewer
  // bind the same port and take half the requests: only SO_REUSEADDR here.
  http.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, reinterpret_cast<const void*>(&yes), sizeof(yes));
  });
  http.set_payload_max_length(1 << 16);
  http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) { return check_origin(req, res); });
  http.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    const std::string what = res.status == 404   ? "no such page or endpoint: " + req.method + " " + req.path
                             : res.status == 413 ? "the request body is larger than 64 KiB"
                                                 : "bad request";
    send_error(res, res.status, what);
  });
  http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    try {
      std::rethrow_exception(ep);
    } catch (const std::invalid_argument& e) {
      send_error(res, 400, e.what());
    } catch (const std::out_of_range& e) {
      send_error(res, 400, e.what());
    } catch (const std::exception& e) {
      send_error(res, 500, e.what());
    }
  });
}

// The page, its script and the render's status.
void ViewerServer::Impl::page_routes() {
  http.Get("/", [](const httplib::Request&, httplib::Response& res) { res.set_content(kViewerHtml, "text/html; charset=utf-8"); });
  http.Get("/viewer.js", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(kViewerJs, "text/javascript; charset=utf-8");
  });
  http.Get("/api/status", [this](const httplib::Request&, httplib::Response& res) { send_json(res, status_json()); });
}

// The render, its sample rate, the library's reference and their difference,
// as PNGs; the linear render as floats.
void ViewerServer::Impl::image_routes() {
  http.Get("/api/image", [this](const httplib::Request& req, httplib::Response& res) {
    send_image_of(req.has_param("kind") ? req.get_param_value("kind") : "render", res);
  });

  // The linear image as float32 RGB, rows from the top (what an EXR holds).
  http.Get("/api/frame", [this](const httplib::Request&, httplib::Response& res) {
    const Image image = session.snapshot().image;
    std::vector<float> data(image.pixels.size() * 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) data[3 * i + c] = float(image.pixels[i][c]);
    res.set_header("X-Width", std::to_string(image.width));
    res.set_header("X-Height", std::to_string(image.height));
    res.set_content(std::string(reinterpret_cast<const char*>(data.data()), data.size() * sizeof(float)),
                    "application/octet-stream");
  });
}

void ViewerServer::Impl::send_image_of(const std::string& kind, httplib::Response& res) {
  double exposure;
  int cap;
  {
    std::lock_guard<std::mutex> lock(mutex);
    exposure = settings.exposure;
    cap = settings.render.ns_aa;
  }
  if (kind == "render") return send_image(res, session.snapshot().image, exposure);
  if (kind == "rate") {
    const Snapshot snap = session.snapshot();
    return send_image(res, sample_rate_image(snap.samples, snap.image.width, snap.image.height, cap), 0.0);
  }
  if (kind != "reference" && kind != "difference")
    throw std::invalid_argument("kind=" + kind + ": expected render, rate, reference or difference");
  std::lock_guard<std::mutex> lock(mutex);
  const LibraryReference* ref = library_reference();
  if (!ref) return send_error(res, 404, "this scene has no library reference image");
  if (kind == "reference") return send_image(res, ref->image, exposure);
  const Image render = session.snapshot().image;
  if (render.width != ref->image.width || render.height != ref->image.height)
    return send_error(res, 409, "the render is " + std::to_string(render.width) + "x" + std::to_string(render.height) +
                                    ", the reference " + std::to_string(ref->image.width) + "x" +
                                    std::to_string(ref->image.height) + ": use the library settings first");
  send_image(res, difference_image(render, ref->image), 0.0);
}

// The render's settings; pausing, resuming, stopping or restarting it;
// rendering one cell of the image.
void ViewerServer::Impl::control_routes() {
  http.Post("/api/settings", [this](const httplib::Request& req, httplib::Response& res) {
    const json body = parse_body(req);
    std::lock_guard<std::mutex> lock(mutex);
    const ViewerSettings next = apply_settings_json(settings, body, options.threads);
    // Exposure only changes how the image is shown: no new render for it.
    json render_part = settings_json(next), old_part = settings_json(settings);
    render_part.erase("exposure");
    old_part.erase("exposure");
    settings = next;
    if (render_part != old_part) restart();
    send_json(res, settings_json(settings));
  });
  http.Post("/api/control", [this](const httplib::Request& req, httplib::Response& res) {
    const std::string action = req.has_param("action") ? req.get_param_value("action") : "";
    std::lock_guard<std::mutex> lock(mutex);
    if (action == "pause") session.set_paused(true);
    else if (action == "resume") session.set_paused(false);
    else if (action == "stop") session.stop();
    else if (action == "restart") restart();
    else throw std::invalid_argument("action=" + action + ": expected pause, resume, stop or restart");
    send_json(res, {{"ok", true}});
  });
  http.Post("/api/cell", [this](const httplib::Request& req, httplib::Response& res) {
    const json body = parse_body(req);
    std::lock_guard<std::mutex> lock(mutex);
    if (body.is_null()) {
      restart();
      return send_json(res, {{"ok", true}});
    }
    const RenderSettings& r = settings.render;
    if (!body.is_array() || body.size() != 4) throw std::invalid_argument("cell: expected [x0, y0, x1, y1] or null");
    for (const json& v : body)
      if (!v.is_number_integer()) throw std::invalid_argument("cell: expected integers, got " + v.dump());
    Cell c{body[0].get<int>(), body[1].get<int>(), body[2].get<int>(), body[3].get<int>()};
    if (c.x0 < 0 || c.y0 < 0 || c.x1 > r.width || c.y1 > r.height || c.empty())
      throw std::invalid_argument("cell: " + body.dump() + " is not a non-empty rectangle inside the " +
                                  std::to_string(r.width) + "x" + std::to_string(r.height) + " image");
    restart(c);
    send_json(res, {{"ok", true}});
  });
}

// The camera: saved as a file, set, or reset to the scene's or the course's.
void ViewerServer::Impl::camera_routes() {
  http.Get("/api/camera", [this](const httplib::Request&, httplib::Response& res) {
    res.set_header("Content-Disposition", "attachment; filename=\"camera.json\"");
    send_json(res, camera_json(session.view()));
  });
  http.Post("/api/camera", [this](const httplib::Request& req, httplib::Response& res) {
    const ViewState v = view_from_json(parse_body(req));
    std::lock_guard<std::mutex> lock(mutex);
    current_view = v;
    restart();
    send_json(res, camera_json(v));
  });
  http.Post("/api/camera/reset", [this](const httplib::Request& req, httplib::Response& res) {
    const std::string to = req.has_param("to") ? req.get_param_value("to") : "scene";
    if (to != "scene" && to != "course") throw std::invalid_argument("to=" + to + ": expected scene or course");
    std::lock_guard<std::mutex> lock(mutex);
    const RenderSettings& r = settings.render;
    const BBox bounds = scene.bounds();
    current_view = to == "scene" ? scene_view : view_of(course_camera(loaded_camera, bounds, r.width, r.height), bounds.centroid());
    restart();
    send_json(res, camera_json(current_view));
  });
}

// The inspectors: a node of the BVH, the path through a pixel.
void ViewerServer::Impl::inspect_routes() {
  http.Get("/api/bvh", [this](const httplib::Request& req, httplib::Response& res) {
    const std::string path = req.has_param("path") ? req.get_param_value("path") : "";
    if (path.size() > 4096) throw std::invalid_argument("path: longer than any tree this viewer walks");
    RenderSettings r = session.settings();
    send_json(res, bvh_node_json(scene, path, session.view().camera(r.width, r.height), r.width, r.height));
  });
  http.Get("/api/pixel", [this](const httplib::Request& req, httplib::Response& res) {
    const RenderSettings r = session.settings();
    const int x = int_param(req, "x", 0, r.width), row = int_param(req, "y", 0, r.height);
    const Snapshot snap = session.snapshot();
    const Camera camera = session.view().camera(r.width, r.height);
    if (!scene.bvh) return send_error(res, 409, "no path can be traced: " + options.scene_error);
    std::unique_ptr<PathTracer> tracer = make_tracer(scene, r);
    json j = pixel_path_json(scene, *tracer, camera, x, row);
    const Spectrum v = snap.image.at(x, row);
    j["value"] = {v.r, v.g, v.b};
    j["samples"] = snap.samples[size_t(row) * r.width + x];
    send_json(res, j);
  });
}

// The render against the scene library's reference, and its settings.
void ViewerServer::Impl::compare_routes() {
  http.Get("/api/compare", [this](const httplib::Request&, httplib::Response& res) { send_json(res, compare_json()); });
  http.Post("/api/compare/library-settings", [this](const httplib::Request&, httplib::Response& res) {
    std::lock_guard<std::mutex> lock(mutex);
    const LibraryReference* ref = library_reference();
    if (!ref) return send_error(res, 404, "this scene is not in the scene library");
    RenderSettings& r = settings.render;
    r.width = ref->settings.width;
    r.height = ref->settings.height;
    r.ns_area_light = ref->settings.ns_area_light;
    r.max_ray_depth = ref->settings.max_ray_depth;
    r.rr_continue_prob = ref->settings.rr_continue_prob;
    r.direct_hemisphere_sample = r.adaptive = false;
    r.accumulate_bounces = true;
    current_view = scene_view;
    restart();
    send_json(res, settings_json(settings));
  });
}

ViewerServer::ViewerServer(Scene& scene, ViewerOptions options) : impl_(std::make_unique<Impl>(scene, std::move(options))) {
  impl_->current_view = impl_->options.course_camera ? impl_->course_view : impl_->scene_view;
}

ViewerServer::~ViewerServer() { stop(); }

int ViewerServer::bind() {
  Impl& m = *impl_;
  if (m.options.port == 0) m.port = m.http.bind_to_any_port("127.0.0.1");
  else m.port = m.http.bind_to_port("127.0.0.1", m.options.port) ? m.options.port : -1;
  return m.port;
}

void ViewerServer::serve() {
  impl_->serving = true;
  impl_->restart();
  impl_->http.listen_after_bind();
  impl_->serving = false;
}

void ViewerServer::stop() {
  impl_->session.stop();
  // httplib's stop() does nothing before its loop runs: wait for the loop
  // when serve() has been called but is not listening yet.
  while (impl_->serving && !impl_->http.is_running() && !impl_->stopped)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  impl_->stopped = true;
  impl_->http.stop();
}

std::string ViewerServer::url() const { return "http://127.0.0.1:" + std::to_string(impl_->port) + "/"; }

int run_viewer(Scene& scene, const ViewerOptions& options) {
  // Ctrl-C and SIGTERM are taken by one thread (sigwait), which stops the
  // server; every other thread, started after this, has them blocked.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGUSR1);  // the server stopped by itself: end the waiter
  // A shell starts a background job with SIGINT ignored, and an ignored
  // signal never reaches sigwait: take them back to the default first.
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  ViewerServer server(scene, options);
  if (server.bind() < 0) {
    std::cerr << "error: --view: cannot listen on 127.0.0.1:" << options.port << " (in use? try --port 0 for any free port)\n";
    return 2;
  }
  std::thread waiter([&] {
    int sig = 0;
    sigwait(&signals, &sig);
    if (sig != SIGUSR1) std::cerr << "\nviewer: " << (sig == SIGINT ? "Ctrl-C" : "SIGTERM") << ": stopping\n";
    server.stop();
  });
  std::cout << "viewer: " << server.url() << "  (open it in a browser; Ctrl-C stops)" << std::endl;
  server.serve();
  pthread_kill(waiter.native_handle(), SIGUSR1);
  waiter.join();
  return 0;
}

// Registers --view with the command line when this object is linked in.
const bool kViewerRegistered = (viewer_entry() = &run_viewer, true);

}  // namespace pt
