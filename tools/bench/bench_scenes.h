#pragma once
// Scenes and rays for the BVH benchmark (pt-bench) and the BVH picture tool
// (pt-bvh-boxes). Everything here is generated from a seed or read from the
// repository's scenes/, so that two runs trace exactly the same rays.
#include <memory>
#include <string>
#include <vector>

#include "core/ray.h"
#include "geometry/mesh.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace pt::bench {

// --- Meshes -------------------------------------------------------------------
// Loop subdivision (Loop 1987, with Warren's vertex weights beta = 3/16 for
// valence 3 and 3/(8n) otherwise): every triangle becomes four. Boundary and
// non-manifold edges get their midpoint; boundary vertices the 1/8-3/4-1/8
// rule; vertices with other than two boundary neighbours stay put. Normals are
// dropped (Scene::add_mesh recomputes them).
Mesh loop_subdivide(const Mesh& in, int levels);

// A "bumpy sphere": a cube-sphere (each cube face an n x n grid of quads, two
// triangles each: 12 n^2 triangles, shared vertices) of radius `radius`,
// displaced radially by a sum of fixed sinusoids of amplitude up to about
// 8% of the radius. n = 289 gives 1,002,252 triangles.
Mesh make_bumpy_sphere(int n, double radius = 1.0);

// --- Scenes -------------------------------------------------------------------
// A benchmark scene: the pt::Scene owns meshes and primitives (its BVH is not
// built here; callers build their own) and a camera that frames it.
struct BenchScene {
  std::string name;         // short, for tables
  std::string description;  // one line: where it comes from
  Scene scene;
  std::vector<Primitive*> prims() const;
  size_t triangle_count() const { return scene.triangle_count(); }
  BBox bounds() const;  // union of the primitives' boxes
};

// The mesh alone (no BSDF), with a camera that frames its bounding box from
// the front-right-above (frame_points over its vertices, vfov 40 degrees).
std::unique_ptr<BenchScene> mesh_scene(const std::string& name, const std::string& description, Mesh mesh);
// Any scene file the framework loads (.json), or a bare .obj (framed as above).
// Throws SceneError.
std::unique_ptr<BenchScene> load_bench_scene(const std::string& path);

// A camera looking at the centre of `b` from direction `from`, as close as it
// can be with every one of `points` inside a square image.
Camera frame_points(const std::vector<Vec3>& points, const BBox& b, const Vec3& from = Vec3(0.3, 0.25, 1.0),
                    double vfov_deg = 40.0);

// Resolves a path relative to the repository (PT_SOURCE_DIR) when it does not
// exist as given.
std::string repo_path(const std::string& path);

// --- Rays ---------------------------------------------------------------------
// Primary rays through the pixel centres of a w x h image, row by row from the
// top (the pinhole model of Camera, written out here so that the benchmark does
// not depend on Part 1's Camera::generate_ray). t in [near_clip, far_clip].
std::vector<Ray> camera_rays(const Camera& camera, int w, int h);

// Incoherent rays: origin o uniform in `b` enlarged by 10% on each side,
// direction towards a second point p drawn the same way (so uniform-ish over
// the sphere, biased towards the box), normalised. Closest-hit rays have
// t in [0, inf); with `segments`, max_t = |p - o| (a shadow ray between two
// points). The same seed gives the same o and p either way.
std::vector<Ray> random_rays(const BBox& b, size_t n, uint64_t seed, bool segments);

// --- Brute force and the machine -----------------------------------------------
// Every primitive in scene order through the virtual Primitive interface (the
// baseline a BVH is measured against; any hit stops at the first hit).
bool brute_closest(const std::vector<Primitive*>& prims, const Ray& r, Intersection* isect);
bool brute_any(const std::vector<Primitive*>& prims, const Ray& r);

// The CPU's model name (/proc/cpuinfo), for reports.
std::string cpu_model();

}  // namespace pt::bench
