// pt-bvh-boxes: the boxes of a BVH at a chosen depth, for the write-up.
//
//   pt-bvh-boxes scenes/meshes/bunny.obj --depth 6 -o boxes.obj [--with-mesh]
//   pt-bvh-boxes scenes/cornell_bunny.json --depth 8 --png boxes.png
//   pt-bvh-boxes scenes/meshes/bunny.obj --depth 6 --builder midpoint-longest -o single_axis.obj
//
// Writes an OBJ that any viewer opens (Blender, MeshLab, an online viewer):
// by default each box as 8 vertices and 12 line elements ('l'); --style faces
// writes each box as 12 triangles, --style beams each edge as a thin square
// beam (12 triangles per edge) for viewers that do not draw lines. The PNG
// is a headless picture: the scene shaded by the angle to the camera, the box
// edges overlaid (full colour in front of the surface, faint behind it).
//
// The tree is the one this binary's Part 2 builds (pt-bvh-boxes: the
// student's; pt-bvh-boxes-reference: the reference), or with --builder one of
// the framework's builders of tests/support/part2_baseline.h, so that a
// single-axis split can be shown beside a three-axis surface-area split
// without editing any code. Only construct_bvh is needed: the picture is
// traced by the framework's own traversal of the tree.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>

#include "bench_scenes.h"
#include "geometry/triangle.h"
#include "render/image.h"
#include "io/image_file.h"
#include "support/bvh_checks.h"
#include "support/part2_baseline.h"

using namespace pt;
using namespace pt::test::part2;

namespace {

const std::map<std::string, SplitMethod> kBuilders = {
    {"mean-sah", SplitMethod::kMeanSAH},
    {"median-sah", SplitMethod::kMedianSAH},
    {"midpoint-sah", SplitMethod::kMidpointSAH},
    {"midpoint-longest", SplitMethod::kMidpointLongest},
    {"mean-longest", SplitMethod::kMeanLongest},
    {"object-median-longest", SplitMethod::kObjectMedianLongest},
    {"midpoint-x", SplitMethod::kMidpointX},
};

std::array<Vec3, 8> corners(const BBox& b) {
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i) c[i] = Vec3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
  return c;
}
// The 12 edges of a box as pairs of corner indices (bit 0: x, bit 1: y, bit 2: z).
constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
// The 12 triangles of a box's surface, outward.
constexpr int kFaces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                               {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

struct ObjWriter {
  std::ofstream out;
  size_t vertices = 0;
  explicit ObjWriter(const std::string& path) : out(path) { out.precision(9); }
  size_t v(const Vec3& p) {
    out << "v " << p.x << " " << p.y << " " << p.z << "\n";
    return ++vertices;  // OBJ indices start at 1
  }
  void box_surface(const BBox& b) {
    auto c = corners(b);
    size_t base = vertices + 1;
    for (const Vec3& p : c) v(p);
    for (const auto& f : kFaces) out << "f " << base + f[0] << " " << base + f[1] << " " << base + f[2] << "\n";
  }
  void box_lines(const BBox& b) {
    auto c = corners(b);
    size_t base = vertices + 1;
    for (const Vec3& p : c) v(p);
    for (const auto& e : kEdges) out << "l " << base + e[0] << " " << base + e[1] << "\n";
  }
  void box_beams(const BBox& b, double w) {
    auto c = corners(b);
    for (const auto& e : kEdges) {
      // An axis-aligned beam of cross-section w x w around the edge.
      BBox beam(c[e[0]], c[e[1]]);
      beam.min -= Vec3(w / 2);
      beam.max += Vec3(w / 2);
      box_surface(beam);
    }
  }
};

Vec3 hue(size_t i) {
  // Golden-ratio hues: neighbouring boxes get distinct colours.
  double h = std::fmod(0.13 + 0.618033988749895 * double(i), 1.0) * 6.0;
  double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
  Vec3 rgb = h < 1 ? Vec3(1, x, 0) : h < 2 ? Vec3(x, 1, 0) : h < 3 ? Vec3(0, 1, x) : h < 4 ? Vec3(0, x, 1) : h < 5 ? Vec3(x, 0, 1) : Vec3(1, 0, x);
  return rgb * rgb;  // to linear-ish, so the PNG's sRGB curve shows saturated colours
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pt-bvh-boxes: writes the boxes of a BVH at one depth as an OBJ (and optionally a PNG) for the write-up."};
  std::string scene_path, out_path = "boxes.obj", style = "lines", builder = "own", png_path;
  int depth = 4;
  size_t leaf_size = 4;
  bool only_depth = false, with_mesh = false;
  double beam_width = 0.0;
  std::vector<int> res{640, 480};
  app.add_option("scene", scene_path, "Scene file (.json) or mesh (.obj)")->required();
  app.add_option("-d,--depth", depth, "Depth of the boxes to show (root = 0)")->check(CLI::NonNegativeNumber);
  app.add_option("-o,--output", out_path, "OBJ to write (\"\" for none)");
  app.add_option("--style", style, "lines: 12 'l' elements per box; faces: 12 triangles per box; beams: each edge a thin beam")
      ->check(CLI::IsMember({"lines", "faces", "beams"}));
  app.add_option("--beam-width", beam_width, "Beam width for --style beams (default 0.3% of the scene diagonal)");
  app.add_flag("--only-depth", only_depth,
               "Only nodes at exactly this depth (default: also the leaves that end above it, so the boxes cover the scene)");
  app.add_flag("--with-mesh", with_mesh, "Also write the scene's triangles (object 'scene') into the OBJ");
  std::string builders = "own";
  for (const auto& b : kBuilders) builders += ", " + b.first;
  app.add_option("--builder", builder,
                 "own: this binary's BVHAccel::construct_bvh; or a framework builder of tests/support/part2_baseline.h")
      ->check(CLI::IsMember([&] {
        std::vector<std::string> v{"own"};
        for (const auto& b : kBuilders) v.push_back(b.first);
        return v;
      }()));
  app.add_option("--leaf-size", leaf_size, "max_leaf_size of the build");
  app.add_option("--png", png_path, "Also render a PNG with the box edges overlaid");
  app.add_option("-r,--resolution", res, "PNG width and height")->expected(2);
  CLI11_PARSE(app, argc, argv);

  try {
    auto s = bench::load_bench_scene(scene_path);
    std::vector<const Primitive*> prims;
    for (const auto& p : s->scene.primitives) prims.push_back(p.get());
    FlatTree tree;
    std::unique_ptr<BVHAccel> bvh;  // keeps `tree.prims` alive for the own build
    if (builder == "own") {
      bvh = std::make_unique<BVHAccel>(s->prims(), leaf_size);
      tree = flatten(*bvh);
    } else {
      tree = build_framework_bvh(prims, leaf_size, kBuilders.at(builder));
    }
    if (tree.nodes.empty()) throw std::runtime_error("the scene has no primitives");

    // The cut at `depth`.
    std::vector<size_t> chosen;
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
      const FlatNode& n = tree.nodes[i];
      if (n.depth == depth || (!only_depth && n.leaf() && n.depth < depth)) chosen.push_back(i);
    }
    const BBox root = tree.nodes[0].bb;
    const double diag = glm::length(root.extent());
    double area = 0.0;
    size_t leaves_above = 0;
    for (size_t i : chosen) {
      area += tree.nodes[i].bb.surface_area();
      leaves_above += tree.nodes[i].depth < depth;
    }
    std::printf("%s: %zu primitives; %s tree: %zu nodes, %zu leaves, depth %d, SAH cost %.2f\n", s->name.c_str(),
                prims.size(), builder == "own" ? "this binary's" : builder.c_str(), tree.nodes.size(),
                tree.leaf_count(), tree.max_depth(), sah_cost(tree));
    std::printf("depth %d: %zu boxes (%zu of them leaves above that depth), total surface %.2f x the root's\n", depth,
                chosen.size(), leaves_above, root.surface_area() > 0 ? area / root.surface_area() : 0.0);
    if (chosen.empty()) std::printf("(the tree is only %d levels deep)\n", tree.max_depth());

    if (!out_path.empty()) {
      ObjWriter w(out_path);
      w.out << "# pt-bvh-boxes " << scene_path << " --depth " << depth << " --builder " << builder << " --style "
            << style << "\n";
      w.out << "# " << chosen.size() << " boxes of a " << tree.nodes.size() << "-node BVH over " << prims.size()
            << " primitives\n";
      if (with_mesh) {
        w.out << "o scene\n";
        for (const auto& m : s->scene.meshes) {
          size_t base = w.vertices + 1;
          for (const Vec3& p : m->positions) w.v(p);
          for (const auto& f : m->faces) w.out << "f " << base + f[0] << " " << base + f[1] << " " << base + f[2] << "\n";
        }
      }
      w.out << "o bvh_depth_" << depth << "\n";
      double bw = beam_width > 0 ? beam_width : 0.003 * diag;
      for (size_t i : chosen) {
        const BBox& b = tree.nodes[i].bb;
        if (style == "lines") w.box_lines(b);
        else if (style == "faces") w.box_surface(b);
        else w.box_beams(b, bw);
      }
      if (!w.out) throw std::runtime_error("cannot write " + out_path);
      std::printf("wrote %s\n", out_path.c_str());
    }

    if (!png_path.empty()) {
      const int W = res[0], H = res[1];
      Camera cam = s->scene.camera;
      cam.set_aspect(double(W) / H);
      std::vector<Ray> rays = bench::camera_rays(cam, W, H);
      Image img(W, H);
      std::vector<double> depth_buf(size_t(W) * H, kInf);
      for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
          Ray r = rays[size_t(y) * W + x];
          Intersection isect;
          if (framework_closest(tree, r, &isect)) {
            double c = 0.15 + 0.6 * std::abs(glm::dot(glm::normalize(isect.n), r.d));
            img.at(x, y) = Spectrum(c);
            depth_buf[size_t(y) * W + x] = isect.t;
          } else {
            img.at(x, y) = Spectrum(0.02, 0.02, 0.03);
          }
        }
      }
      // Box edges: walk each edge in 3D in sub-pixel steps, project, and blend
      // by whether the point lies in front of the surface seen at that pixel.
      const Mat3 w2c = glm::transpose(cam.c2w);
      const double tx = std::tan(glm::radians(cam.hfov) / 2), ty = std::tan(glm::radians(cam.vfov) / 2);
      auto project = [&](const Vec3& p, double* px, double* py) {
        Vec3 q = w2c * (p - cam.pos);
        if (q.z >= -1e-9) return false;
        *px = (q.x / -q.z / tx + 1.0) / 2.0 * W;
        *py = (1.0 - (q.y / -q.z / ty + 1.0) / 2.0) * H;
        return true;
      };
      std::vector<Spectrum> overlay(size_t(W) * H);
      std::vector<double> overlay_strength(size_t(W) * H, 0.0);
      for (size_t k = 0; k < chosen.size(); ++k) {
        Vec3 colour = hue(k);
        auto c = corners(tree.nodes[chosen[k]].bb);
        for (const auto& e : kEdges) {
          double ax, ay, bx, by;
          bool va = project(c[e[0]], &ax, &ay), vb = project(c[e[1]], &bx, &by);
          double len = va && vb ? std::hypot(bx - ax, by - ay) : double(W + H);
          int steps = std::max(2, int(std::min(len, 4.0 * (W + H)) * 2));
          for (int i = 0; i <= steps; ++i) {
            Vec3 p = glm::mix(c[e[0]], c[e[1]], double(i) / steps);
            double px, py;
            if (!project(p, &px, &py)) continue;
            int ix = int(std::floor(px)), iy = int(std::floor(py));
            if (ix < 0 || iy < 0 || ix >= W || iy >= H) continue;
            double dist = glm::length(p - cam.pos);
            bool front = dist <= depth_buf[size_t(iy) * W + ix] * (1.0 + 1e-6);
            size_t at = size_t(iy) * W + ix;
            double strength = front ? 1.0 : 0.3;
            if (strength >= overlay_strength[at]) {
              overlay_strength[at] = strength;
              overlay[at] = colour;
            }
          }
        }
      }
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          size_t at = size_t(y) * W + x;
          if (overlay_strength[at] > 0) img.at(x, y) = glm::mix(img.at(x, y), overlay[at], overlay_strength[at]);
        }
      write_png(png_path, img);
      std::printf("wrote %s\n", png_path.c_str());
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
