#include "support/part2_scenes.h"

#include <cmath>

#include "core/rng.h"
#include "core/sampling.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace pt::test::part2 {

namespace {

Vec3 uniform_in(Rng& rng, const Vec3& lo, const Vec3& hi) {
  return lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * (hi - lo);
}
Vec3 unit(Rng& rng) { return sample_uniform_sphere(rng.uniform2()); }
double log_uniform(Rng& rng, double lo, double hi) { return lo * std::pow(hi / lo, rng.uniform()); }

// A random triangle around `c` with edges of about `size`.
void add_random_triangle(Part2Scene& s, Rng& rng, const Vec3& c, double size) {
  Vec3 a = c + 0.6 * size * unit(rng), b = c + 0.6 * size * unit(rng), d = c + 0.6 * size * unit(rng);
  s.add_triangle(a, b, d);
}

void quad(Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  m.faces.push_back({a, b, c});
  m.faces.push_back({a, c, d});
}

}  // namespace

Part2Scene::Part2Scene() = default;
Part2Scene::Part2Scene(Part2Scene&&) noexcept = default;
Part2Scene& Part2Scene::operator=(Part2Scene&&) noexcept = default;
Part2Scene::~Part2Scene() = default;

void Part2Scene::add_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  if (!soup_) {
    meshes_.push_back(std::make_unique<Mesh>());
    soup_ = meshes_.back().get();
    soup_->name = "soup";
  }
  uint32_t i = uint32_t(soup_->positions.size());
  soup_->positions.insert(soup_->positions.end(), {a, b, c});
  soup_->faces.push_back({i, i + 1, i + 2});
  // Soup vertices are not shared: each one's normal is its own triangle's,
  // computed as Mesh::compute_vertex_normals would.
  Vec3 n = glm::cross(b - a, c - a);
  double len = glm::length(n);
  n = len > 0.0 ? n / len : Vec3(0.0, 0.0, 1.0);
  soup_->normals.insert(soup_->normals.end(), {n, n, n});
  prims_.push_back(std::make_unique<Triangle>(soup_, i, i + 1, i + 2));
}

void Part2Scene::add_mesh(Mesh mesh) {
  if (mesh.normals.size() != mesh.positions.size()) mesh.compute_vertex_normals();
  meshes_.push_back(std::make_unique<Mesh>(std::move(mesh)));
  const Mesh* m = meshes_.back().get();
  for (const auto& f : m->faces) prims_.push_back(std::make_unique<Triangle>(m, f[0], f[1], f[2]));
}

void Part2Scene::add_sphere(const Vec3& center, double radius) {
  prims_.push_back(std::make_unique<Sphere>(center, radius, nullptr));
}

std::vector<const Primitive*> Part2Scene::primitives() const {
  std::vector<const Primitive*> out;
  out.reserve(prims_.size());
  for (const auto& p : prims_) out.push_back(p.get());
  return out;
}

BBox Part2Scene::bounds() const {
  BBox b;
  for (const auto& p : prims_) b.expand(p->get_bbox());
  return b;
}

Mesh make_torus(double R, double r, int nu, int nv, double bump, uint64_t seed) {
  Rng rng(seed, 11);
  Mesh m;
  m.name = "torus";
  for (int i = 0; i < nu; ++i) {
    double u = 2.0 * kPi * i / nu;
    for (int j = 0; j < nv; ++j) {
      double v = 2.0 * kPi * j / nv;
      double rr = r * (1.0 + bump * (2.0 * rng.uniform() - 1.0));
      m.positions.push_back(
          Vec3((R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u), rr * std::sin(v)));
    }
  }
  auto id = [&](int i, int j) { return uint32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  m.compute_vertex_normals();
  return m;
}

Mesh make_uv_sphere(const Vec3& center, double radius, int nu, int nv) {
  Mesh m;
  m.name = "sphere";
  m.positions.push_back(center + Vec3(0, 0, radius));  // north pole
  for (int j = 1; j < nv; ++j) {
    double theta = kPi * j / nv;
    for (int i = 0; i < nu; ++i) {
      double phi = 2.0 * kPi * i / nu;
      m.positions.push_back(center + radius * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                                   std::cos(theta)));
    }
  }
  m.positions.push_back(center - Vec3(0, 0, radius));  // south pole
  auto id = [&](int j, int i) { return uint32_t(1 + (j - 1) * nu + (i + nu) % nu); };
  const uint32_t south = uint32_t(m.positions.size() - 1);
  for (int i = 0; i < nu; ++i) {
    m.faces.push_back({0, id(1, i), id(1, i + 1)});
    m.faces.push_back({south, id(nv - 1, i + 1), id(nv - 1, i)});
    for (int j = 1; j + 1 < nv; ++j) quad(m, id(j, i), id(j + 1, i), id(j + 1, i + 1), id(j, i + 1));
  }
  m.compute_vertex_normals();
  return m;
}

Mesh make_flat_grid(int n, double size, double z0, double jitter, uint64_t seed) {
  Rng rng(seed, 12);
  Mesh m;
  m.name = "flat grid";
  const double cell = size / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Vec3 p(-0.5 * size + i * cell, -0.5 * size + j * cell, z0);
      if (i > 0 && i < n && j > 0 && j < n) {
        p.x += jitter * cell * (2.0 * rng.uniform() - 1.0);
        p.y += jitter * cell * (2.0 * rng.uniform() - 1.0);
      }
      m.positions.push_back(p);
    }
  auto id = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  m.compute_vertex_normals();
  return m;
}

Part2Scene make_soup(uint64_t seed, int triangles, int spheres) {
  Rng rng(seed, 13);
  Part2Scene s;
  s.name = "triangle soup with spheres";
  // Interleave spheres among the triangles so that they do not sit at the end.
  int placed_spheres = 0;
  for (int i = 0; i < triangles; ++i) {
    add_random_triangle(s, rng, uniform_in(rng, Vec3(-10), Vec3(10)), log_uniform(rng, 0.05, 2.0));
    while (placed_spheres < spheres && (placed_spheres + 1) * double(triangles) <= (i + 1) * double(spheres)) {
      s.add_sphere(uniform_in(rng, Vec3(-10), Vec3(10)), 0.1 + 0.9 * rng.uniform());
      ++placed_spheres;
    }
  }
  for (; placed_spheres < spheres; ++placed_spheres) s.add_sphere(uniform_in(rng, Vec3(-10), Vec3(10)), 0.1 + 0.9 * rng.uniform());
  return s;
}

Part2Scene make_mesh_scene(uint64_t seed) {
  Part2Scene s;
  s.name = "torus mesh (20,000 triangles) with a sphere mesh through its hole";
  s.add_mesh(make_torus(3.0, 1.0, 100, 100, 0.02, seed));
  s.add_mesh(make_uv_sphere(Vec3(0.0, 0.0, 0.5), 1.2, 24, 12));
  return s;
}

Part2Scene make_copies(int n) {
  Part2Scene s;
  s.name = std::to_string(n) + " copies of one triangle";
  for (int i = 0; i < n; ++i) s.add_triangle(Vec3(-1.0, -0.5, 0.25), Vec3(1.5, -0.25, -0.5), Vec3(0.0, 1.0, 0.5));
  return s;
}

Part2Scene make_coplanar_centroids(uint64_t seed, int n) {
  Rng rng(seed, 14);
  Part2Scene s;
  s.name = "triangles whose centroids all lie on the plane z = 0";
  for (int i = 0; i < n; ++i) {
    Vec3 c = uniform_in(rng, Vec3(-10, -10, 0), Vec3(10, 10, 0));
    double h = 0.05 + 0.5 * rng.uniform();  // vertices at z = +h, -h and 0: box and vertex centroids at z = 0
    Vec3 a = c + Vec3(0.6 * (rng.uniform() - 0.5), 0.6 * (rng.uniform() - 0.5), 0.0);
    Vec3 b = c + Vec3(0.6 * (rng.uniform() - 0.5), 0.6 * (rng.uniform() - 0.5), 0.0);
    Vec3 d = c + Vec3(0.6 * (rng.uniform() - 0.5), 0.6 * (rng.uniform() - 0.5), 0.0);
    a.z = h;
    b.z = -h;
    d.z = 0.0;
    s.add_triangle(a, b, d);
  }
  return s;
}

Part2Scene make_huge_among_tiny(uint64_t seed, int n) {
  Rng rng(seed, 15);
  Part2Scene s;
  s.name = "one huge triangle among tiny ones";
  for (int i = 0; i < n; ++i) {
    if (i == n / 3) s.add_triangle(Vec3(-1000, -1000, -3), Vec3(1000, -1000, 2), Vec3(0, 1000, 0.5));
    add_random_triangle(s, rng, uniform_in(rng, Vec3(-10), Vec3(10)), 0.02);
  }
  return s;
}

Part2Scene make_clustered(uint64_t seed) {
  Rng rng(seed, 16);
  Part2Scene s;
  s.name = "clustered: clumps of very different populations in a large empty volume";
  for (int k = 0; k < 40; ++k) {
    Vec3 c = uniform_in(rng, Vec3(-200), Vec3(200));
    int count = int(log_uniform(rng, 8, 1500));
    double spread = log_uniform(rng, 0.5, 8.0);
    double size = spread * log_uniform(rng, 0.02, 0.2);
    for (int i = 0; i < count; ++i) {
      Vec3 g(0.0);
      for (int a = 0; a < 3; ++a) g[a] = spread * (rng.uniform() + rng.uniform() + rng.uniform() - 1.5);
      add_random_triangle(s, rng, c + g, size);
    }
  }
  for (int i = 0; i < 20; ++i) add_random_triangle(s, rng, uniform_in(rng, Vec3(-200), Vec3(200)), 30.0);
  return s;
}

Part2Scene make_fibres(uint64_t seed, int n) {
  Rng rng(seed, 17);
  Part2Scene s;
  s.name = "elongated: a bundle of long thin fibres";
  for (int i = 0; i < n; ++i) {
    Vec3 a(200.0 * rng.uniform(), 8.0 * rng.uniform(), 8.0 * rng.uniform());
    Vec3 w = 0.02 * unit(rng);
    s.add_triangle(a, a + Vec3(400.0, 0.0, 0.0) + w, a + Vec3(400.0, 0.0, 0.0) - w + 0.02 * unit(rng));
  }
  return s;
}

Part2Scene make_layers(uint64_t seed, int layers) {
  Rng rng(seed, 18);
  Part2Scene s;
  s.name = std::to_string(layers) + " stacked sheets";
  for (int l = 0; l < layers; ++l) {
    Mesh m = make_flat_grid(16, 16.0, l, 0.0, 0);  // unit cells, centred, in the plane z = l
    m.name = "sheet";
    for (Vec3& p : m.positions) p.z += 0.2 * (rng.uniform() - 0.5);
    m.normals.clear();  // add_mesh recomputes them for the bumped sheet
    s.add_mesh(std::move(m));
  }
  return s;
}

std::vector<Ray> make_rays(const Part2Scene& scene, int n, uint64_t seed) {
  Rng rng(seed, 19);
  const BBox b = scene.bounds();
  const Vec3 c = b.centroid();
  const double radius = 0.5 * glm::length(b.extent()) + 1e-3;
  const auto prims = scene.primitives();
  std::vector<Ray> rays;
  rays.reserve(n);
  for (int i = 0; i < n; ++i) {
    Vec3 o, d;
    switch (i % 3) {
      case 0: {  // from outside at a point of a random primitive
        const Primitive* p = prims[size_t(rng.uniform() * prims.size()) % prims.size()];
        Vec3 target;
        if (auto* t = dynamic_cast<const Triangle*>(p)) {
          double u = rng.uniform(), v = rng.uniform();
          if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
          target = (1.0 - u - v) * t->p1() + u * t->p2() + v * t->p3();
        } else {
          BBox pb = p->get_bbox();
          target = uniform_in(rng, pb.min, pb.max);
        }
        o = c + 1.5 * radius * unit(rng);
        d = glm::normalize(target - o);
        break;
      }
      case 1:  // from inside the scene's box
        o = uniform_in(rng, b.min, b.max);
        d = unit(rng);
        break;
      default:  // from outside, anywhere
        o = c + 1.5 * radius * unit(rng);
        d = unit(rng);
        break;
    }
    rays.emplace_back(o, d * (0.5 + 1.5 * rng.uniform()));
  }
  return rays;
}

std::vector<Ray> make_layer_rays(const Part2Scene& scene, int n, uint64_t seed) {
  Rng rng(seed, 20);
  const BBox b = scene.bounds();
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    bool down = i % 2 == 0;
    Vec3 o(b.min.x + 2.0 + (b.extent().x - 4.0) * rng.uniform(), b.min.y + 2.0 + (b.extent().y - 4.0) * rng.uniform(),
           down ? b.max.z + 1.0 : b.min.z - 1.0);
    Vec3 d(0.3 * (rng.uniform() - 0.5), 0.3 * (rng.uniform() - 0.5), down ? -1.0 : 1.0);
    rays.emplace_back(o, glm::normalize(d));
  }
  return rays;
}

}  // namespace pt::test::part2
