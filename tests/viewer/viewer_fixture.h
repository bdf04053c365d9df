#pragma once
// A viewer served in-process on a free port of 127.0.0.1, with cpp-httplib's
// client pointed at it, for the endpoint tests (test_viewer_*.cpp).
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/viewer_inspect.h"
#include "app/viewer_server.h"
#include "io/scene_loader.h"
#include "pt_source_dir.h"

namespace pt::test {

using json = nlohmann::json;

inline std::string scene_file(const std::string& name) { return std::string(PT_SOURCE_DIR) + "/scenes/" + name; }

class ServedViewer {
 public:
  // Tiny default settings so that every render takes a fraction of a second.
  // A non-empty scene_error serves the scene without a BVH, as --view does
  // when construct_bvh throws.
  explicit ServedViewer(const std::string& scene, TracerFactory make_tracer = {}, RenderSettings s = small_settings(),
                        const std::string& scene_error = "")
      : loaded_(load_scene(scene_file(scene), scene_error.empty() ? BuildBvh::Yes : BuildBvh::No)) {
    ViewerOptions options;
    options.scene_error = scene_error;
    options.scene_path = scene_file(scene);
    options.settings.render = s;
    options.threads = 2;
    options.make_tracer = std::move(make_tracer);
    server_ = std::make_unique<ViewerServer>(loaded_.scene, options);
    port_ = server_->bind();
    thread_ = std::thread([this] { server_->serve(); });
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client_->set_read_timeout(60, 0);
  }
  ~ServedViewer() {
    server_->stop();
    thread_.join();
  }

  static RenderSettings small_settings() {
    RenderSettings s;
    s.width = 32;
    s.height = 24;
    s.ns_aa = 4;
    s.max_ray_depth = 3;
    return s;
  }

  int port() const { return port_; }
  httplib::Client& client() { return *client_; }
  const Scene& scene() const { return loaded_.scene; }

  // The JSON body of GET path, asserting the status.
  json get(const std::string& path, int status = 200) {
    auto res = client_->Get(path.c_str());
    EXPECT_TRUE(res) << "GET " << path << ": no answer";
    if (!res) return json();
    EXPECT_EQ(res->status, status) << "GET " << path << ": " << res->body;
    return json::parse(res->body, nullptr, false);
  }
  json post(const std::string& path, const std::string& body, int status = 200) {
    auto res = client_->Post(path.c_str(), body, "application/json");
    EXPECT_TRUE(res) << "POST " << path << ": no answer";
    if (!res) return json();
    EXPECT_EQ(res->status, status) << "POST " << path << " " << body << ": " << res->body;
    return json::parse(res->body, nullptr, false);
  }
  json post(const std::string& path, const json& body, int status = 200) { return post(path, body.dump(), status); }

  // Waits (up to a minute, however slow the machine) until the render is
  // no longer running; returns the final status.
  json wait_until_finished() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    json st;
    while (std::chrono::steady_clock::now() < deadline) {
      st = get("/api/status");
      if (st.is_object() && st["state"] != "rendering") return st;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ADD_FAILURE() << "the render did not finish within 60 s: " << st.dump();
    return st;
  }

  // The linear frame as the viewer holds it (float RGB, rows from the top).
  std::vector<float> frame(int* width, int* height) {
    auto res = client_->Get("/api/frame");
    EXPECT_TRUE(res && res->status == 200);
    if (!res) return {};
    *width = std::stoi(res->get_header_value("X-Width"));
    *height = std::stoi(res->get_header_value("X-Height"));
    std::vector<float> data(res->body.size() / sizeof(float));
    std::memcpy(data.data(), res->body.data(), data.size() * sizeof(float));
    return data;
  }

 private:
  LoadedScene loaded_;
  std::unique_ptr<ViewerServer> server_;
  int port_ = -1;
  std::thread thread_;
  std::unique_ptr<httplib::Client> client_;
};

// The pixel inspector's path through the centre of a 33 x 33 image of a unit
// sphere made of BSDF B, seen and lit (by a point light) from (0, 0, 3).
template <class B>
json centre_path_on_sphere_of() {
  Scene scene;
  scene.add_sphere(Vec3(0.0), 1.0, scene.add_bsdf<B>());
  scene.add_light<PointLight>(Spectrum(5.0), Vec3(0.0, 0.0, 3.0));
  scene.build();
  RenderSettings s;
  s.width = s.height = 33;
  s.max_ray_depth = 3;
  PathTracer tracer(scene, s);
  const ViewState view{Vec3(0.0, 0.0, 3.0), Vec3(0.0), Vec3(0.0, 1.0, 0.0), 40.0};
  return pixel_path_json(scene, tracer, view.camera(33, 33), 16, 16);
}

}  // namespace pt::test
