// What the viewer refuses, and how it fails: every bad request gets a 4xx
// with a message, a request naming another host or coming from another
// origin is refused, a task that throws shows on the page while the server
// stays up, and Ctrl-C ends the process cleanly.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/not_implemented.h"
#include "viewer_fixture.h"

namespace pt::test {
namespace {

// A page on another site whose name resolves to 127.0.0.1 (DNS rebinding)
// sends its own name as Host: refused, whatever it asks for.
TEST(ViewerErrors, RefusesAnotherHostOrOrigin) {
  ServedViewer v("tests/one_sphere.json");
  for (const char* host : {"evil.example:80", "evil.example", "127.0.0.1", "127.0.0.2:1", ""}) {
    auto res = v.client().Get("/api/status", httplib::Headers{{"Host", host}});
    ASSERT_TRUE(res) << host;
    EXPECT_EQ(res->status, 403) << "Host: " << host;
    EXPECT_NE(res->body.find("is not this viewer"), std::string::npos) << res->body;
    auto page = v.client().Get("/", httplib::Headers{{"Host", host}});
    EXPECT_EQ(page->status, 403) << "the page itself, Host: " << host;
  }
  const std::string localhost = "localhost:" + std::to_string(v.port());
  auto ok = v.client().Get("/api/status", httplib::Headers{{"Host", localhost}});
  EXPECT_EQ(ok->status, 200);
  // A change posted by another site's page (its Origin) is refused.
  auto res = v.client().Post("/api/control?action=stop", httplib::Headers{{"Origin", "http://evil.example"}}, "",
                             "text/plain");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 403);
  EXPECT_NE(v.get("/api/status")["state"], "stopped");
  // The viewer's own page may (sendBeacon on closing sends its Origin).
  auto own = v.client().Post("/api/control?action=stop",
                             httplib::Headers{{"Origin", "http://127.0.0.1:" + std::to_string(v.port())}}, "", "text/plain");
  EXPECT_EQ(own->status, 200);
  EXPECT_EQ(v.wait_until_finished()["state"], "stopped");
}

// A second viewer cannot take the port of a running one (it would share its
// requests): its bind fails, and --view says so.
TEST(ViewerErrors, ASecondViewerCannotTakeTheSamePort) {
  ServedViewer first("tests/one_sphere.json");
  LoadedScene loaded = load_scene(scene_file("tests/one_sphere.json"));
  ViewerOptions options;
  options.scene_path = scene_file("tests/one_sphere.json");
  options.port = first.port();
  ViewerServer second(loaded.scene, options);
  EXPECT_EQ(second.bind(), -1);
  EXPECT_EQ(first.get("/api/status")["scene"], scene_file("tests/one_sphere.json"));
}

TEST(ViewerErrors, BadRequestsGetA4xxWithAMessage) {
  ServedViewer v("tests/one_sphere.json");
  struct Bad {
    std::string method, path, body;
    int status;
    std::string says;
  };
  const std::vector<Bad> cases = {
      {"GET", "/etc/passwd", "", 404, "no such page"},
      {"GET", "/api/nothing", "", 404, "no such page"},
      {"POST", "/api/settings", "{not json", 400, "not JSON"},
      {"POST", "/api/settings", "[1, 2]", 400, "expected a JSON object"},
      {"POST", "/api/settings", R"({"samples": 0})", 400, "samples: 0 is not in [1,"},
      {"POST", "/api/settings", R"({"samples": "4"})", 400, "samples: expected an integer"},
      {"POST", "/api/settings", R"({"samples": 2.5})", 400, "samples: expected an integer"},
      {"POST", "/api/settings", R"({"light_samples": 100000})", 400, "light_samples"},
      {"POST", "/api/settings", R"({"max_depth": -1})", 400, "max_depth"},
      {"POST", "/api/settings", R"({"accumulate": 2})", 400, "accumulate"},
      {"POST", "/api/settings", R"({"hemisphere": 1})", 400, "hemisphere: expected true or false"},
      {"POST", "/api/settings", R"({"adaptive": [0, 0.05]})", 400, "adaptive batch"},
      {"POST", "/api/settings", R"({"adaptive": [32, -1]})", 400, "adaptive tolerance"},
      {"POST", "/api/settings", R"({"adaptive": 5})", 400, "expected null or [batch, tolerance]"},
      {"POST", "/api/settings", R"({"rr": 0})", 400, "rr"},
      {"POST", "/api/settings", R"({"rr": 1.5})", 400, "rr"},
      {"POST", "/api/settings", R"({"exposure": 100})", 400, "exposure"},
      {"POST", "/api/settings", R"({"width": 16384, "height": 16384})", 400, "pixels"},
      {"POST", "/api/settings", R"({"bounces": 3})", 400, "bounces: not a setting"},
      {"POST", "/api/camera", R"({"position": [0,0,3], "target": [0,0,3], "up": [0,1,0], "vfov": 40})", 400,
       "target: must differ"},
      {"POST", "/api/camera", R"({"position": [0,0,3], "target": [0,0,0], "up": [0,0,1], "vfov": 40})", 400,
       "up: must not be zero or parallel"},
      {"POST", "/api/camera", R"({"position": [0,0,3], "target": [0,0,0], "up": [0,1,0], "vfov": 180})", 400, "vfov"},
      {"POST", "/api/camera", R"({"position": [0,0], "target": [0,0,0], "up": [0,1,0], "vfov": 40})", 400,
       "position: expected [x, y, z]"},
      {"POST", "/api/camera", R"({"position": [0,0,3], "target": [0,0,0], "vfov": 40})", 400, "up: missing"},
      {"POST", "/api/camera", R"({"position": [0,0,3], "target": [0,0,0], "up": [0,1,0], "vfov": 40, "zoom": 2})", 400,
       "zoom: not a camera field"},
      {"POST", "/api/camera/reset?to=elsewhere", "", 400, "expected scene or course"},
      {"POST", "/api/control?action=explode", "", 400, "expected pause, resume, stop or restart"},
      {"POST", "/api/cell", "[0, 0, 999, 10]", 400, "inside the 32x24 image"},
      {"POST", "/api/cell", "[5, 5, 5, 10]", 400, "non-empty rectangle"},
      {"POST", "/api/cell", "[0, 0, 1]", 400, "expected [x0, y0, x1, y1]"},
      {"GET", "/api/pixel?x=32&y=0", "", 400, "x=32 is not an integer in [0, 32)"},
      {"GET", "/api/pixel?x=1&y=-1", "", 400, "y=-1"},
      {"GET", "/api/pixel?x=1e1&y=0", "", 400, "x=1e1"},
      {"GET", "/api/pixel?x=1", "", 400, "missing parameter y"},
      {"GET", "/api/image?kind=secret", "", 400, "expected render, rate, reference or difference"},
      {"GET", "/api/bvh?path=lrx", "", 400, "step 3 is 'x'"},
      {"POST", "/api/status", "", 404, ""},  // a GET endpoint
      {"POST", "/api/settings", std::string(100000, ' '), 413, ""},  // beyond the body limit
  };
  for (const Bad& b : cases) {
    auto res = b.method == "GET" ? v.client().Get(b.path.c_str()) : v.client().Post(b.path.c_str(), b.body, "application/json");
    ASSERT_TRUE(res) << b.method << " " << b.path;
    EXPECT_EQ(res->status, b.status) << b.method << " " << b.path << " " << b.body.substr(0, 80) << ": " << res->body;
    EXPECT_NE(res->body.find(b.says), std::string::npos) << b.path << " says " << res->body << ", expected '" << b.says << "'";
    if (b.status != 413) {
      EXPECT_NE(res->body.find("\"error\""), std::string::npos) << res->body;
    }
  }
  // Nothing of that changed the settings or stopped the server.
  const json st = v.wait_until_finished();
  EXPECT_EQ(st["state"], "done");
  EXPECT_EQ(st["settings"]["samples"], 4);
  EXPECT_EQ(st["generation"], 1);
}

// The stub of a task: a render that reaches it stops with its message, which
// the status (and so the page) shows; the server goes on answering.
struct ThrowingTracer : PathTracer {
  using PathTracer::PathTracer;
  Spectrum est_radiance_global_illumination(const Ray&, Rng&) const override {
    throw NotImplemented("P4T3 est_radiance_global_illumination");
  }
};

TEST(ViewerErrors, AThrowingTaskShowsItsMessageAndTheServerStaysUp) {
  ServedViewer v("tests/one_sphere.json", [](const Scene& s, const RenderSettings& r) {
    return std::make_unique<ThrowingTracer>(s, r);
  });
  json st = v.wait_until_finished();
  EXPECT_EQ(st["state"], "error");
  EXPECT_EQ(st["error"], "not implemented: P4T3 est_radiance_global_illumination");
  // The page's banner names the option the command line names (app/part_origins.h).
  EXPECT_NE(st["hint"].get<std::string>().find("-DPT_REFERENCE_PARTS=\"4\""), std::string::npos) << st.dump();
  // Still serving: the page, the BVH, a new setting (which fails the same way).
  auto page = v.client().Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("<canvas"), std::string::npos);
  EXPECT_EQ(v.get("/api/bvh")["count"], v.scene().primitives.size());
  v.post("/api/settings", json{{"samples", 8}});
  st = v.wait_until_finished();
  EXPECT_EQ(st["state"], "error");
  EXPECT_EQ(st["generation"], 2);
}

// construct_bvh threw while --view loaded the scene: the page says so, and
// everything that needs the tree answers with that message.
TEST(ViewerErrors, ABvhThatCouldNotBeBuiltIsShownNotFatal) {
  const std::string why = "building the BVH: not implemented: P2T1 BVHAccel::construct_bvh";
  ServedViewer v("tests/one_sphere.json", {}, ServedViewer::small_settings(), why);
  const json st = v.wait_until_finished();
  EXPECT_EQ(st["state"], "error");
  EXPECT_EQ(st["error"], why);
  const json bvh = v.get("/api/bvh", 400);
  EXPECT_NE(bvh["error"].get<std::string>().find("no BVH"), std::string::npos) << bvh.dump();
  const json pixel = v.get("/api/pixel?x=1&y=1", 409);
  EXPECT_NE(pixel["error"].get<std::string>().find(why), std::string::npos) << pixel.dump();
  EXPECT_EQ(v.get("/api/camera/reset?to=course", 404).is_object(), true);  // a POST endpoint: GET is unknown
  v.post("/api/camera/reset?to=course", std::string());  // the camera still moves
}

// The inspector names the task that threw in the path it could trace.
TEST(ViewerErrors, AThrowingTaskEndsTheInspectedPathWithItsName) {
  struct ThrowingDirect : BSDF {
    Spectrum f(const Vec3&, const Vec3&) const override { throw NotImplemented("P3T1 DiffuseBSDF::f"); }
    Spectrum sample_f(const Vec3&, Vec3*, double*, Rng&) const override { throw NotImplemented("P3T1 DiffuseBSDF::sample_f"); }
  };
  const json p = centre_path_on_sphere_of<ThrowingDirect>();
  ASSERT_TRUE(p.contains("error"));
  EXPECT_EQ(p["error"], "not implemented: P3T1 DiffuseBSDF::f (in P3T5 one_bounce_radiance)");
}

// `pathtracer --view` as a student runs it: it prints its URL, serves, and
// Ctrl-C ends it with status 0 and no thread left behind (the process exits).
TEST(ViewerErrors, CtrlCExitsCleanly) {
  int out[2];
  ASSERT_EQ(pipe(out), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(out[1], 1);
    close(out[0]);
    const std::string scene = scene_file("cornell_spheres.json");
    execl(PT_PATHTRACER_REFERENCE, "pathtracer-reference", "--view", scene.c_str(), "--port", "0", "-r", "32", "24", "-s",
          "100000", "-t", "1", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(out[1]);
  std::string line;
  char c;
  while (read(out[0], &c, 1) == 1 && c != '\n') line += c;
  close(out[0]);
  const size_t at = line.find("http://127.0.0.1:");
  ASSERT_NE(at, std::string::npos) << "printed: " << line;
  const int port = std::stoi(line.substr(at + 17));
  httplib::Client client("127.0.0.1", port);
  auto res = client.Get("/api/status");
  ASSERT_TRUE(res);
  EXPECT_NE(res->body.find("\"state\":\"rendering\""), std::string::npos) << res->body;  // 100000 spp: still going
  kill(pid, SIGINT);
  int status = 0;
  pid_t done = 0;
  // Bounded: a minute at most, polled (a hung viewer fails, it does not hang the test).
  for (int i = 0; i < 6000 && (done = waitpid(pid, &status, WNOHANG)) == 0; ++i) usleep(10000);
  if (done == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    FAIL() << "the viewer did not exit within 60 s of Ctrl-C";
  }
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_FALSE(client.Get("/api/status")) << "still answering after exit";
}

}  // namespace
}  // namespace pt::test
