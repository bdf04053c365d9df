// The viewer's render endpoints: progress, every setting, the camera file
// round trip, cells, and the flip against the library. Each render is tiny
// (32 x 24 at 4 spp unless said), and every check waits for a state with a
// bounded timeout: nothing here depends on how fast the machine is.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

#include "app/cli.h"
#include "io/image_file.h"
#include "render/limits.h"
#include "viewer_fixture.h"

namespace pt::test {
namespace {

namespace fs = std::filesystem;

// A file name in the temporary folder that no other process running this test uses.
std::string temp_file(const std::string& name) {
  return (fs::temp_directory_path() / ("pt_viewer_" + std::to_string(getpid()) + "_" + name)).string();
}

TEST(ViewerRender, ProgressReachesTheSampleCountPassByPass) {
  RenderSettings s = ServedViewer::small_settings();
  s.ns_aa = 10;  // passes of 4, 4 and 2
  ServedViewer v("cornell_spheres.json", {}, s);
  const json st = v.wait_until_finished();
  EXPECT_EQ(st["state"], "done");
  EXPECT_EQ(st["spp"], 10.0);
  EXPECT_EQ(st["target_spp"], 10);
  EXPECT_GT(st["rays_per_second"].get<double>(), 0.0);
  EXPECT_EQ(st["eta_seconds"], 0.0);
  // Every pixel took all its samples, and the image is not black.
  for (auto [x, y] : {std::pair{0, 0}, {31, 23}, {16, 12}}) {
    const json p = v.get("/api/pixel?x=" + std::to_string(x) + "&y=" + std::to_string(y));
    EXPECT_EQ(p["samples"], 10) << x << "," << y;
  }
  int w, h;
  const std::vector<float> f = v.frame(&w, &h);
  ASSERT_EQ(f.size(), size_t(32 * 24 * 3));
  double sum = 0;
  for (float x : f) sum += x;
  EXPECT_GT(sum, 0.0);
  // The RGBA image the page draws has the same size.
  auto img = v.client().Get("/api/image?kind=render");
  ASSERT_TRUE(img);
  EXPECT_EQ(img->body.size(), size_t(32 * 24 * 4));
}

TEST(ViewerRender, PauseResumeStopAndRestart) {
  RenderSettings s = ServedViewer::small_settings();
  s.ns_aa = 64;
  ServedViewer v("cornell_spheres.json", {}, s);
  v.post("/api/control?action=pause", std::string());
  json st = v.get("/api/status");
  // Paused, unless the render had already finished.
  EXPECT_TRUE(st["state"] == "paused" || st["state"] == "done") << st.dump();
  v.post("/api/control?action=resume", std::string());
  v.post("/api/control?action=stop", std::string());
  st = v.wait_until_finished();
  EXPECT_TRUE(st["state"] == "stopped" || st["spp"] == 64.0) << st.dump();
  const uint64_t generation = st["generation"];
  v.post("/api/control?action=restart", std::string());
  st = v.wait_until_finished();
  EXPECT_EQ(st["state"], "done");
  EXPECT_EQ(st["spp"], 64.0);  // one render at a time: the stopped one adds nothing
  EXPECT_EQ(st["generation"], generation + 1);
}

// Renders `args` headless (the same binary's command line, in-process) and
// returns the EXR it writes.
Image render_headless(std::vector<std::string> args, const std::string& name) {
  const std::string png = temp_file(name + ".png");
  args.insert(args.begin(), "pathtracer");
  for (std::string extra : {"-q", "-t", "2", "-f"}) args.push_back(extra);
  args.push_back(png);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  EXPECT_EQ(run_cli(int(argv.size()), argv.data()), 0);
  Image out = read_exr(png.substr(0, png.size() - 4) + ".exr");
  fs::remove(png);
  fs::remove(png.substr(0, png.size() - 4) + ".exr");
  fs::remove(png.substr(0, png.size() - 4) + "_rate.png");
  return out;
}

void expect_frame_equals(ServedViewer& v, const Image& headless, const std::string& what) {
  int w, h;
  const std::vector<float> f = v.frame(&w, &h);
  ASSERT_EQ(w, headless.width) << what;
  ASSERT_EQ(h, headless.height) << what;
  size_t differ = 0;
  for (size_t i = 0; i < headless.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) differ += f[3 * i + c] != float(headless.pixels[i][c]);
  EXPECT_EQ(differ, 0u) << what << ": the viewer's frame and the headless render differ in " << differ << " values";
}

// Each setting reaches the estimators: the viewer's first pass (spp <= 4)
// with a setting equals the headless render with the same flag, exactly,
// and differs from the render without it (so the setting was not ignored).
TEST(ViewerRender, EverySettingRendersAsItsFlag) {
  ServedViewer v("cornell_spheres.json");
  v.wait_until_finished();
  const std::string scene = scene_file("cornell_spheres.json");
  // The plain settings' flags, each unless the case gives its own.
  const std::vector<std::vector<std::string>> defaults = {{"-r", "32", "24"}, {"-s", "4"}, {"-m", "3"}};
  int w, h;
  const std::vector<float> plain = v.frame(&w, &h);
  struct Case {
    json settings;
    std::vector<std::string> flags;
  };
  const std::vector<Case> cases = {
      {{{"light_samples", 3}}, {"-l", "3"}},
      {{{"max_depth", 0}}, {"-m", "0"}},
      {{{"max_depth", 2}, {"accumulate", 0}}, {"-m", "2", "-o", "0"}},
      {{{"hemisphere", true}}, {"-H"}},
      {{{"rr", 0.2}, {"max_depth", 6}}, {"--rr", "0.2", "-m", "6"}},
      {{{"samples", 2}}, {"-s", "2"}},
      {{{"seed", 7}}, {"--seed", "7"}},
      {{{"adaptive", {2, 0.5}}, {"samples", 4}}, {"-a", "2", "0.5", "-s", "4"}},
      {{{"width", 20}, {"height", 10}}, {"-r", "20", "10"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.settings.dump());
    // From the plain settings each time: one setting at a time.
    v.post("/api/settings", json{{"samples", 4}, {"light_samples", 1}, {"max_depth", 3}, {"accumulate", 1},
                                  {"hemisphere", false}, {"rr", 0.7}, {"seed", 0}, {"adaptive", nullptr},
                                  {"width", 32}, {"height", 24}});
    const json echoed = v.post("/api/settings", c.settings);
    for (const auto& [key, value] : c.settings.items()) EXPECT_EQ(echoed[key], value) << key;
    const json st = v.wait_until_finished();
    ASSERT_EQ(st["state"], "done") << st.dump();
    std::vector<std::string> args = {scene};
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    for (const auto& d : defaults)
      if (std::find(c.flags.begin(), c.flags.end(), d[0]) == c.flags.end()) args.insert(args.end(), d.begin(), d.end());
    expect_frame_equals(v, render_headless(args, "setting"), c.settings.dump());
    EXPECT_NE(v.frame(&w, &h), plain) << "the setting changed nothing";
  }
}

TEST(ViewerRender, ExposureRedrawsWithoutANewRender) {
  ServedViewer v("cornell_spheres.json");
  const json st = v.wait_until_finished();
  auto dark = v.client().Get("/api/image?kind=render");
  const json echoed = v.post("/api/settings", json{{"exposure", 2}});
  EXPECT_EQ(echoed["exposure"], 2);
  EXPECT_EQ(v.get("/api/status")["generation"], st["generation"]);
  auto bright = v.client().Get("/api/image?kind=render");
  ASSERT_TRUE(dark && bright);
  ASSERT_EQ(dark->body.size(), bright->body.size());
  long brighter = 0;
  for (size_t i = 0; i < dark->body.size(); ++i) brighter += uint8_t(bright->body[i]) > uint8_t(dark->body[i]);
  EXPECT_GT(brighter, 100);
}

// A moved view saved as a camera file renders, through -c, the viewer's frame.
TEST(ViewerRender, CameraFileRoundTrip) {
  ServedViewer v("cornell_spheres.json");
  v.wait_until_finished();
  json cam = v.get("/api/camera");
  cam["position"] = {0.7, 0.9, 1.8};  // an orbit and a zoom, as the page would send
  cam["target"] = {0.05, 0.45, 0.0};
  cam["vfov"] = 41.5;
  v.post("/api/camera", cam);
  v.wait_until_finished();
  const json saved = v.get("/api/camera");
  EXPECT_EQ(saved, cam);
  const std::string file = temp_file("camera.json");
  FILE* out = std::fopen(file.c_str(), "w");
  ASSERT_NE(out, nullptr);
  std::fputs(saved.dump(2).c_str(), out);
  std::fclose(out);
  const Image headless =
      render_headless({scene_file("cornell_spheres.json"), "-c", file, "-r", "32", "24", "-s", "4", "-m", "3"}, "camera");
  expect_frame_equals(v, headless, "-c " + file);
  fs::remove(file);
  // Resetting gives the scene's camera back, and --course-camera another view.
  const json scene_cam = v.post("/api/camera/reset?to=scene", std::string());
  EXPECT_NE(scene_cam, cam);
  const json course = v.post("/api/camera/reset?to=course", std::string());
  EXPECT_NE(course, scene_cam);
  EXPECT_EQ(v.get("/api/camera"), course);
}

// Counts the camera rays it is asked about and scales their radiance by
// `gain`, so that a test can tell which pixels a render touched.
struct CountingTracer : PathTracer {
  CountingTracer(const Scene& s, const RenderSettings& r, std::atomic<long>* calls, std::atomic<int>* gain)
      : PathTracer(s, r), calls(calls), gain(gain) {}
  Spectrum est_radiance_global_illumination(const Ray& r, Rng& rng) const override {
    ++*calls;
    return PathTracer::est_radiance_global_illumination(r, rng) * double(gain->load());
  }
  std::atomic<long>* calls;
  std::atomic<int>* gain;
};

// A cell renders only its pixels; the rest of the image stays as it was.
TEST(ViewerRender, CellRendersOnlyItsPixels) {
  std::atomic<long> calls{0};
  std::atomic<int> gain{1};
  ServedViewer v("cornell_spheres.json", [&](const Scene& s, const RenderSettings& r) {
    return std::make_unique<CountingTracer>(s, r, &calls, &gain);
  });
  v.wait_until_finished();
  EXPECT_EQ(calls, 32 * 24 * 4);
  int w, h;
  const std::vector<float> before = v.frame(&w, &h);
  calls = 0;
  gain = 2;
  v.post("/api/cell", json{8, 4, 20, 14});
  const json st = v.wait_until_finished();
  EXPECT_EQ(st["cell"], json({8, 4, 20, 14}));
  EXPECT_EQ(st["spp"], 4.0);
  EXPECT_EQ(calls, 12 * 10 * 4);
  const std::vector<float> after = v.frame(&w, &h);
  for (int row = 0; row < h; ++row)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t i = 3 * (size_t(row) * w + x) + c;
        const bool inside = x >= 8 && x < 20 && row >= 4 && row < 14;
        ASSERT_EQ(after[i], inside ? 2 * before[i] : before[i]) << x << "," << row << (inside ? " inside" : " outside");
      }
  // null: the whole image again.
  calls = 0;
  v.post("/api/cell", std::string("null"));
  v.wait_until_finished();
  EXPECT_EQ(calls, 32 * 24 * 4);
}

// The flip: the library's stored image of this scene, the difference, and the
// live relMSE within what the error model explains at the current spp.
TEST(ViewerRender, CompareWithTheLibraryReference) {
  ServedViewer v("cornell_spheres.json");
  json c = v.get("/api/compare");
  ASSERT_EQ(c["available"], true) << c.dump();
  EXPECT_EQ(c["name"], "cornell_spheres");
  EXPECT_FALSE(c.contains("relmse"));  // 32 x 24: not the reference's size
  v.get("/api/image?kind=difference", 409);
  const json lib = v.post("/api/compare/library-settings", std::string());
  EXPECT_EQ(lib["width"], 256);
  EXPECT_EQ(lib["max_depth"], 5);
  const json st = v.wait_until_finished();
  ASSERT_EQ(st["state"], "done");
  c = v.get("/api/compare");
  EXPECT_EQ(c["differs"], json::array());
  ASSERT_TRUE(c.contains("relmse")) << c.dump();
  EXPECT_EQ(c["spp"], 4.0);
  EXPECT_GT(c["relmse"].get<double>(), 0.0);
  // A correct render (the reference's own code) is within the library test's bound.
  EXPECT_LE(c["relmse"].get<double>(), c["bound_relmse"].get<double>()) << c.dump();
  auto ref = v.client().Get("/api/image?kind=reference");
  auto diff = v.client().Get("/api/image?kind=difference");
  ASSERT_TRUE(ref && diff);
  EXPECT_EQ(ref->status, 200);
  EXPECT_EQ(diff->status, 200);
  EXPECT_EQ(ref->body.size(), size_t(256 * 192 * 4));
  EXPECT_EQ(diff->body.size(), size_t(256 * 192 * 4));
  // A scene outside the library says so.
  ServedViewer other("tests/one_sphere.json");
  const json none = other.get("/api/compare");
  EXPECT_EQ(none["available"], false);
  EXPECT_NE(none["reason"].get<std::string>().find("not in the scene library"), std::string::npos);
  other.get("/api/image?kind=reference", 404);
}

}  // namespace
}  // namespace pt::test
