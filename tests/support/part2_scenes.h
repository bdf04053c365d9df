#pragma once
// Geometry and rays for the Part 2 (BVH) tests, generated from a seed so that
// no test depends on a file: triangle soups with spheres, tessellated meshes,
// and the inputs on which split methods are known to struggle.
#include <memory>
#include <string>
#include <vector>

#include "core/ray.h"
#include "geometry/mesh.h"
#include "geometry/primitive.h"

namespace pt::test::part2 {

// Owns the meshes and primitives of a test scene. Loose triangles go into one
// internal "soup" mesh (three vertices each); meshes keep their own vertices.
class Part2Scene {
 public:
  Part2Scene();
  Part2Scene(Part2Scene&&) noexcept;
  Part2Scene& operator=(Part2Scene&&) noexcept;
  ~Part2Scene();

  void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c);
  void add_mesh(Mesh mesh);  // one Triangle per face
  void add_sphere(const Vec3& center, double radius);

  // The primitives in the order they were added (the linear scan's order).
  std::vector<const Primitive*> primitives() const;
  size_t size() const { return prims_.size(); }
  BBox bounds() const;
  std::string name;

 private:
  std::vector<std::unique_ptr<Mesh>> meshes_;
  Mesh* soup_ = nullptr;
  std::vector<std::unique_ptr<Primitive>> prims_;
};

// --- Meshes ---------------------------------------------------------------
// A torus around the z axis, radii R (ring) and r (tube), nu x nv quads split
// into 2 nu nv triangles; `bump` displaces vertices radially by up to
// bump * r (seeded) so that the mesh is not perfectly regular.
Mesh make_torus(double R, double r, int nu, int nv, double bump, uint64_t seed);
// A latitude-longitude sphere of 2 nu (nv - 1) triangles (no slivers at the poles).
Mesh make_uv_sphere(const Vec3& center, double radius, int nu, int nv);
// A flat n x n grid of quads (2 n^2 triangles) in the plane z = z0 covering
// [-size/2, size/2]^2; interior vertices jittered in x and y by up to
// jitter x cell (z stays exactly z0, so every box is flat in z).
Mesh make_flat_grid(int n, double size, double z0, double jitter, uint64_t seed);

// --- Scenes -----------------------------------------------------------------
// `triangles` random triangles (edge lengths log-uniform in [0.05, 2], random
// orientation) and `spheres` spheres (radius in [0.1, 1]) in [-10, 10]^3.
Part2Scene make_soup(uint64_t seed, int triangles, int spheres);
// A torus of ~20k triangles (100 x 100 quads), two interlocked by a sphere mesh.
Part2Scene make_mesh_scene(uint64_t seed);
// `n` identical copies of one triangle: every centroid is the same point.
Part2Scene make_copies(int n);
// `n` triangles whose box centroids (and vertex averages) all lie exactly on
// the plane z = 0, although the triangles themselves are tilted out of it.
Part2Scene make_coplanar_centroids(uint64_t seed, int n);
// One triangle 2,000 units across among `n` tiny ones (edges ~0.02) in [-10, 10]^3.
Part2Scene make_huge_among_tiny(uint64_t seed, int n);
// Clustered: dense clumps of small triangles of very different populations
// and sizes, scattered through a large empty volume, with a few loose big triangles.
Part2Scene make_clustered(uint64_t seed);
// Elongated: a bundle of long thin fibres (hair, cables), each a sliver
// triangle 400 units long along x, spread 200 units in x and 8 in y and z.
Part2Scene make_fibres(uint64_t seed, int n);
// `layers` parallel sheets (16 x 16 quads each, gently bumped) stacked along z
// one unit apart, each 16 x 16 units: a ray along z crosses them all.
Part2Scene make_layers(uint64_t seed, int layers);

// --- Rays -------------------------------------------------------------------
// A mix, all seeded: a third aimed from outside the scene at a random point of
// a random primitive (mostly hits), a third from random points inside the
// scene's box in uniform directions, a third from outside in uniform
// directions (mostly misses). Direction lengths vary in [0.5, 2] (t is in
// units of d). min_t = 0, max_t = inf.
std::vector<Ray> make_rays(const Part2Scene& scene, int n, uint64_t seed);
// Rays through the layered scene, roughly along +z or -z (half each, tilted
// by up to ~17 degrees), starting above or below the stack.
std::vector<Ray> make_layer_rays(const Part2Scene& scene, int n, uint64_t seed);

}  // namespace pt::test::part2
