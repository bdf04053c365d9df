#pragma once
// `pathtracer --view`: an HTTP server on 127.0.0.1 (cpp-httplib) that serves
// the viewer page and the render's data, and steers one RenderSession.
// It answers only requests whose Host header names it (no DNS rebinding),
// refuses cross-origin changes, and answers every bad request with a 4xx and
// a JSON {"error": message}.
#include <memory>
#include <string>

#include "app/viewer_settings.h"
#include "scene/scene.h"

namespace pt {

struct ViewerOptions {
  std::string scene_path;
  ViewerSettings settings;
  int threads = 1;
  bool course_camera = false;  // start from --course-camera's view
  int port = 0;                // 0: any free port
  TracerFactory make_tracer;   // empty: the PathTracer the binary was built with
  std::string scene_error;     // why the scene has no BVH (a task threw): every render fails with it
};

class ViewerServer {
 public:
  // `scene` (its BVH built) must outlive the server.
  ViewerServer(Scene& scene, ViewerOptions options);
  ~ViewerServer();

  // Binds 127.0.0.1:options.port (any free port when 0); returns the port, or
  // -1 when the port cannot be had.
  int bind();
  // Serves until stop(); starts the first render.
  void serve();
  void stop();
  std::string url() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The command line's --view: serves until Ctrl-C (SIGINT) or SIGTERM, then
// stops the render and returns 0; 2 when the port cannot be had.
int run_viewer(Scene& scene, const ViewerOptions& options);

}  // namespace pt
