// pt-procedural-mesh: writes the library's large procedural scene, a bumpy
// sphere of any size on a floor under a sun and a sky, as an OBJ and a JSON
// scene beside it (the scene refers to the OBJ by its file name).
//
//   pt-procedural-mesh -o build/scenes/bumpy_sphere                 # n = 289: 1,002,252 triangles
//   pt-procedural-mesh -o /tmp/bumpy_50k --triangles 50000          # the nearest size: n = 65, 50,700
//
// The mesh is pt-bench's "bumpy-sphere" (make_bumpy_sphere in
// tools/bench/bench_scenes.h: a cube-sphere of 12 n^2 triangles displaced by
// fixed sinusoids), so a study over mesh size renders the same shape at every
// size. Nothing here is random: the same n writes the same files.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_scenes.h"

namespace {

using FilePtr = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

FilePtr open_or_throw(const std::string& path) {
  FilePtr f(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!f) throw std::runtime_error(path + ": cannot open for writing");
  return f;
}

void close_or_throw(FilePtr f, const std::string& path) {
  bool ok = std::ferror(f.get()) == 0;
  ok = std::fclose(f.release()) == 0 && ok;  // a full disk shows here, not at fprintf
  if (!ok) throw std::runtime_error(path + ": write failed");
}

// Positions and faces only: the loader computes smooth normals (OBJ faces
// counter-clockwise seen from outside, as make_bumpy_sphere winds them).
void write_obj(const pt::Mesh& m, const std::string& path, int n) {
  FilePtr f = open_or_throw(path);
  std::fprintf(f.get(), "# pt-procedural-mesh: bumpy sphere, n = %d, %zu vertices, %zu triangles\n", n,
               m.positions.size(), m.faces.size());
  for (const pt::Vec3& p : m.positions) std::fprintf(f.get(), "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
  for (const auto& t : m.faces) std::fprintf(f.get(), "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
  close_or_throw(std::move(f), path);
}

// The sphere has radius 1 at the origin; its bumps reach about 8% in and out,
// so the floor sits just below the lowest point.
nlohmann::ordered_json scene_json(const std::string& obj_name, int n, size_t triangles) {
  using J = nlohmann::ordered_json;
  J s;
  s["description"] = "pt-procedural-mesh: a bumpy sphere (radius 1, n = " + std::to_string(n) + ", " +
                     std::to_string(triangles) +
                     " triangles) on a floor under a low sun and a pale sky, for BVH work. Generated at build time "
                     "(tools/procedural_mesh.cpp), not stored.";
  s["camera"] = {{"position", {1.6, 1.1, 3.9}}, {"target", {0.0, -0.05, 0.0}}, {"vfov", 36}};
  s["materials"] = {{"sphere", {{"type", "diffuse"}, {"albedo", {0.7, 0.55, 0.4}}}},
                    {"floor", {{"type", "diffuse"}, {"albedo", {0.5, 0.5, 0.5}}}}};
  s["lights"] = J::array({J{{"type", "directional"}, {"radiance", {2.2, 2.0, 1.7}}, {"direction", {-0.6, -1.0, -0.35}}},
                          J{{"type", "sky"}, {"radiance", {0.12, 0.16, 0.24}}}});
  s["shapes"] = J::array({J{{"type", "mesh"}, {"file", obj_name}, {"material", "sphere"}},
                          J{{"type", "quad"},
                            {"center", {0.0, -1.1, 0.0}},
                            {"edge_x", {0.0, 0.0, 12.0}},
                            {"edge_y", {12.0, 0.0, 0.0}},
                            {"material", "floor"}}});
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes a bumpy-sphere scene of any size: PREFIX.obj (the mesh) and PREFIX.json (the scene)."};
  std::string prefix;
  int n = 289;
  long long triangles = 0;
  app.add_option("-o,--output", prefix, "Output path without extension")->required();
  app.add_option("-n", n, "Grid size per cube face: 12 n^2 triangles (289: 1,002,252)")->check(CLI::Range(1, 2000));
  app.add_option("--triangles", triangles, "Target triangle count instead of -n (the nearest 12 n^2)")
      ->check(CLI::Range(12LL, 48000000LL));
  CLI11_PARSE(app, argc, argv);
  if (triangles > 0) n = std::max(1, int(std::lround(std::sqrt(double(triangles) / 12.0))));

  try {
    pt::Mesh mesh = pt::bench::make_bumpy_sphere(n);
    const std::string obj = prefix + ".obj", json = prefix + ".json";
    const std::string obj_name = obj.substr(obj.find_last_of('/') + 1);
    write_obj(mesh, obj, n);
    FilePtr f = open_or_throw(json);
    std::string text = scene_json(obj_name, n, mesh.faces.size()).dump(2) + "\n";
    std::fwrite(text.data(), 1, text.size(), f.get());
    close_or_throw(std::move(f), json);
    std::printf("wrote %s (%zu triangles) and %s\n", obj.c_str(), mesh.faces.size(), json.c_str());
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
