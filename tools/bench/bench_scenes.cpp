#include "bench_scenes.h"

#include <cmath>
#include <fstream>
#include <unordered_map>

#include "core/rng.h"
#include "io/obj_loader.h"
#include "io/scene_loader.h"
#include "pt_source_dir.h"

namespace pt::bench {

// --- Loop subdivision -----------------------------------------------------------
namespace {

uint64_t edge_key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(a) << 32) | b;
}

struct EdgeInfo {
  uint32_t a = 0, b = 0;   // endpoints
  uint32_t opp[2] = {0, 0};  // the vertices opposite the edge in its first two faces
  int faces = 0;
  uint32_t new_index = 0;
};

Mesh loop_once(const Mesh& in) {
  const size_t nv = in.positions.size();
  std::unordered_map<uint64_t, uint32_t> edge_of;  // key -> index into edges
  std::vector<EdgeInfo> edges;
  edge_of.reserve(in.faces.size() * 2);
  edges.reserve(in.faces.size() * 3 / 2 + 16);
  std::vector<std::array<uint32_t, 3>> face_edges(in.faces.size());
  for (size_t f = 0; f < in.faces.size(); ++f) {
    const auto& v = in.faces[f];
    for (int k = 0; k < 3; ++k) {
      uint32_t a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
      auto [it, fresh] = edge_of.try_emplace(edge_key(a, b), uint32_t(edges.size()));
      if (fresh) edges.push_back(EdgeInfo{a, b, {0, 0}, 0, 0});
      EdgeInfo& e = edges[it->second];
      if (e.faces < 2) e.opp[e.faces] = c;
      ++e.faces;
      face_edges[f][k] = it->second;
    }
  }

  Mesh out;
  out.name = in.name;
  out.bsdf = in.bsdf;
  out.positions.resize(nv + edges.size());

  // Even (old) vertices.
  std::vector<Vec3> ring_sum(nv, Vec3(0.0)), boundary_sum(nv, Vec3(0.0));
  std::vector<int> valence(nv, 0), boundary_count(nv, 0);
  for (const EdgeInfo& e : edges) {
    ring_sum[e.a] += in.positions[e.b];
    ring_sum[e.b] += in.positions[e.a];
    ++valence[e.a];
    ++valence[e.b];
    if (e.faces != 2) {
      boundary_sum[e.a] += in.positions[e.b];
      boundary_sum[e.b] += in.positions[e.a];
      ++boundary_count[e.a];
      ++boundary_count[e.b];
    }
  }
  for (size_t i = 0; i < nv; ++i) {
    const Vec3& p = in.positions[i];
    if (boundary_count[i] == 2) {
      out.positions[i] = 0.75 * p + 0.125 * boundary_sum[i];
    } else if (boundary_count[i] > 0 || valence[i] < 3) {
      out.positions[i] = p;  // a corner or a non-manifold vertex: keep it
    } else {
      int n = valence[i];
      double beta = n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
      out.positions[i] = (1.0 - n * beta) * p + beta * ring_sum[i];
    }
  }
  // Odd (edge) vertices.
  for (size_t k = 0; k < edges.size(); ++k) {
    EdgeInfo& e = edges[k];
    e.new_index = uint32_t(nv + k);
    const Vec3 &a = in.positions[e.a], &b = in.positions[e.b];
    out.positions[e.new_index] = e.faces == 2 ? 0.375 * (a + b) + 0.125 * (in.positions[e.opp[0]] + in.positions[e.opp[1]])
                                              : 0.5 * (a + b);
  }
  out.faces.reserve(in.faces.size() * 4);
  for (size_t f = 0; f < in.faces.size(); ++f) {
    const auto& v = in.faces[f];
    // face_edges[f][k] is the edge from v[k] to v[k+1].
    uint32_t e01 = edges[face_edges[f][0]].new_index, e12 = edges[face_edges[f][1]].new_index,
             e20 = edges[face_edges[f][2]].new_index;
    out.faces.push_back({v[0], e01, e20});
    out.faces.push_back({v[1], e12, e01});
    out.faces.push_back({v[2], e20, e12});
    out.faces.push_back({e01, e12, e20});
  }
  return out;
}

}  // namespace

Mesh loop_subdivide(const Mesh& in, int levels) {
  Mesh m = in;
  m.normals.clear();
  for (int i = 0; i < levels; ++i) m = loop_once(m);
  return m;
}

// --- Bumpy sphere ---------------------------------------------------------------
Mesh make_bumpy_sphere(int n, double radius) {
  Mesh m;
  m.name = "bumpy_sphere";
  // Vertices are keyed by their integer lattice point on the cube [0, n]^3, so
  // that the grids of neighbouring faces share their edge vertices exactly.
  std::unordered_map<uint64_t, uint32_t> index_of;
  index_of.reserve(size_t(6) * (n + 1) * (n + 1));
  auto vertex = [&](int i, int j, int k) -> uint32_t {
    uint64_t key = (uint64_t(i) << 42) | (uint64_t(j) << 21) | uint64_t(k);
    auto [it, fresh] = index_of.try_emplace(key, uint32_t(m.positions.size()));
    if (fresh) {
      Vec3 c(2.0 * i / n - 1.0, 2.0 * j / n - 1.0, 2.0 * k / n - 1.0);
      Vec3 u = glm::normalize(c);
      double bump = 0.05 * std::sin(9.0 * u.x + 0.3) * std::sin(9.0 * u.y + 1.1) * std::sin(9.0 * u.z + 2.3) +
                    0.02 * std::sin(23.0 * u.x + 23.0 * u.y) * std::cos(19.0 * u.z - 7.0 * u.x) +
                    0.008 * std::sin(61.0 * u.y + 0.5) * std::sin(57.0 * u.z + 47.0 * u.x);
      m.positions.push_back(radius * (1.0 + bump) * u);
    }
    return it->second;
  };
  // Each face: a fixed axis at 0 or n, the two others running over the grid,
  // wound so that the normal points outwards.
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      auto lattice = [&](int s, int t) {
        int p[3];
        p[axis] = side ? n : 0;
        p[a1] = s;
        p[a2] = t;
        return vertex(p[0], p[1], p[2]);
      };
      for (int s = 0; s < n; ++s) {
        for (int t = 0; t < n; ++t) {
          uint32_t v00 = lattice(s, t), v10 = lattice(s + 1, t), v11 = lattice(s + 1, t + 1), v01 = lattice(s, t + 1);
          if (side) {
            m.faces.push_back({v00, v10, v11});
            m.faces.push_back({v00, v11, v01});
          } else {
            m.faces.push_back({v00, v11, v10});
            m.faces.push_back({v00, v01, v11});
          }
        }
      }
    }
  }
  return m;
}

// --- Scenes ---------------------------------------------------------------------
std::vector<Primitive*> BenchScene::prims() const {
  std::vector<Primitive*> p;
  p.reserve(scene.primitives.size());
  for (const auto& q : scene.primitives) p.push_back(q.get());
  return p;
}

BBox BenchScene::bounds() const {
  BBox b;
  for (const auto& p : scene.primitives) b.expand(p->get_bbox());
  return b;
}

Camera frame_points(const std::vector<Vec3>& points, const BBox& b, const Vec3& from, double vfov_deg) {
  Vec3 c = b.centroid();
  double radius = 0.5 * glm::length(b.extent());
  if (!(radius > 0.0)) radius = 1.0;
  // Orientation first (any distance), then the nearest distance at which every
  // point projects inside a square image: point q (from the centre, in camera
  // axes right/up/back) needs d >= q.back + max(|q.right|, |q.up|) / tan(fov/2).
  Vec3 dir = glm::normalize(from);
  Camera probe(c + dir * radius, c, Vec3(0.0, 1.0, 0.0), vfov_deg, vfov_deg);
  double tan_half = std::tan(glm::radians(vfov_deg) / 2.0), dist = 0.0;
  for (const Vec3& p : points) {
    Vec3 q = p - c;
    double qr = glm::dot(q, probe.c2w[0]), qu = glm::dot(q, probe.c2w[1]), qb = glm::dot(q, probe.c2w[2]);
    dist = std::max(dist, qb + std::max(std::abs(qr), std::abs(qu)) / tan_half);
  }
  dist = std::max(dist * 1.02, 1e-3 * radius);
  return Camera(c + dist * dir, c, Vec3(0.0, 1.0, 0.0), vfov_deg, vfov_deg);
}

std::unique_ptr<BenchScene> mesh_scene(const std::string& name, const std::string& description, Mesh mesh) {
  auto s = std::make_unique<BenchScene>();
  s->name = name;
  s->description = description;
  const Mesh* m = s->scene.add_mesh(std::move(mesh));
  s->scene.camera = frame_points(m->positions, s->bounds());
  return s;
}

std::string repo_path(const std::string& path) {
  if (std::ifstream(path).good()) return path;
  std::string p = std::string(PT_SOURCE_DIR) + "/" + path;
  if (std::ifstream(p).good()) return p;
  return path;
}

std::unique_ptr<BenchScene> load_bench_scene(const std::string& path_in) {
  std::string path = repo_path(path_in);
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  std::string base = path.substr(path.find_last_of('/') + 1);
  if (ext == ".obj" || ext == ".OBJ") {
    std::vector<std::string> warnings;
    Mesh m = load_obj(path, MeshTransform{}, &warnings);
    return mesh_scene(base, path_in, std::move(m));
  }
  LoadedScene loaded = load_scene(path);
  auto s = std::make_unique<BenchScene>();
  s->name = base;
  s->description = path_in;
  s->scene = std::move(loaded.scene);
  s->scene.bvh.reset();  // callers build their own
  return s;
}

// --- Rays -----------------------------------------------------------------------
std::vector<Ray> camera_rays(const Camera& cam, int w, int h) {
  std::vector<Ray> rays;
  rays.reserve(size_t(w) * h);
  double tx = std::tan(glm::radians(cam.hfov) / 2.0), ty = std::tan(glm::radians(cam.vfov) / 2.0);
  for (int j = h - 1; j >= 0; --j) {
    for (int i = 0; i < w; ++i) {
      double x = (i + 0.5) / w, y = (j + 0.5) / h;
      Vec3 sensor((2.0 * x - 1.0) * tx, (2.0 * y - 1.0) * ty, -1.0);
      Ray r(cam.pos, glm::normalize(cam.c2w * sensor));
      r.min_t = cam.near_clip;
      r.max_t = cam.far_clip;
      rays.push_back(r);
    }
  }
  return rays;
}

std::vector<Ray> random_rays(const BBox& b, size_t n, uint64_t seed, bool segments) {
  Vec3 lo = b.min - 0.1 * b.extent(), ext = 1.2 * b.extent();
  Rng rng(seed, 7);
  std::vector<Ray> rays;
  rays.reserve(n);
  while (rays.size() < n) {
    Vec3 o = lo + ext * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
    Vec3 p = lo + ext * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
    double len = glm::length(p - o);
    if (!(len > 0.0)) continue;
    Ray r(o, (p - o) / len);
    r.min_t = 0.0;
    r.max_t = segments ? len : kInf;
    rays.push_back(r);
  }
  return rays;
}

// --- Brute force and the machine -----------------------------------------------
bool brute_closest(const std::vector<Primitive*>& prims, const Ray& r, Intersection* isect) {
  bool hit = false;
  for (const Primitive* p : prims) hit |= p->intersect(r, isect);
  return hit;
}
bool brute_any(const std::vector<Primitive*>& prims, const Ray& r) {
  for (const Primitive* p : prims)
    if (p->has_intersection(r)) return true;
  return false;
}

std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

}  // namespace pt::bench
