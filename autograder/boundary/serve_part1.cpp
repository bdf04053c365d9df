// The worker's Part 1: the verifier's calls (proxies_part1.cpp) answered by
// the student's task functions, on objects rebuilt from what crossed.
#include "geometry/mesh.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "hit_codec.h"
#include "remote_tracer.h"
#include "scene/bsdf.h"
#include "scene/camera.h"

namespace pt::boundary {
namespace {

// The BSDF of the primitive asked, when the verifier's has one: it only
// needs to be told apart from "nothing" and "something else".
const BSDF* own_bsdf() {
  static const DiffuseBSDF b{Spectrum(0.5)};
  return &b;
}
HitSide side_of(const Primitive* asked) { return {asked, elsewhere_primitive(), asked->get_bsdf(), elsewhere_bsdf()}; }

// Runs one query on `prim` and writes the answer as proxies_part1.cpp reads it.
template <class Query>
void answer_query(const Primitive& prim, Reader& in, Writer& out, Query query) {
  const auto ray = in.get<Ray>();
  const bool with_hit = in.get<uint8_t>() != 0;
  const HitSide side = side_of(&prim);
  Intersection hit;
  if (with_hit) get_hit(in, hit, side);
  const bool result = query(ray, with_hit ? &hit : nullptr);
  out.put(static_cast<uint8_t>(result)).put(ray.min_t).put(ray.max_t);
  if (with_hit) put_hit(out, hit, side);
}

struct TriangleCall {
  Mesh mesh;
  explicit TriangleCall(Reader& in) {
    mesh.positions.resize(3);
    mesh.normals.resize(3);
    for (Vec3& p : mesh.positions) in.get(p);
    for (Vec3& n : mesh.normals) in.get(n);
    mesh.faces.push_back({0u, 1u, 2u});
    mesh.bsdf = in.get<uint8_t>() ? own_bsdf() : nullptr;
  }
};

Sphere sphere_from(Reader& in) {
  const auto o = in.get<Vec3>();
  const auto r = in.get<double>(), r2 = in.get<double>();
  Sphere s(o, r, in.get<uint8_t>() ? own_bsdf() : nullptr);
  s.r2 = r2;
  return s;
}

}  // namespace

void serve_task_calls(Link& link) {
  link.on(Call::GenerateRay, [](Reader& in, Writer& out) {
    const auto camera = in.get<Camera>();
    const auto x = in.get<double>(), y = in.get<double>();
    out.put(camera.generate_ray(x, y));
  });
  link.on(Call::RaytracePixel,
          [&link](Reader& in, Writer& out) { serve_pixel(link, in, out, &PathTracer::raytrace_pixel); });
  auto triangle = [](bool closest) {
    return [closest](Reader& in, Writer& out) {
      const TriangleCall t(in);
      const Triangle tri(&t.mesh, 0, 1, 2);
      answer_query(tri, in, out, [&](const Ray& r, Intersection* hit) {
        return closest ? tri.intersect(r, hit) : tri.has_intersection(r);
      });
    };
  };
  link.on(Call::TriangleHas, triangle(false));
  link.on(Call::TriangleIntersect, triangle(true));
  link.on(Call::SphereTest, [](Reader& in, Writer& out) {
    const Sphere s = sphere_from(in);
    const auto ray = in.get<Ray>();
    if (in.get<uint8_t>()) throw std::runtime_error("Sphere::test takes no hit record");
    auto t1 = in.get<double>(), t2 = in.get<double>();
    const bool roots = s.test(ray, t1, t2);
    out.put(static_cast<uint8_t>(roots)).put(t1).put(t2);
  });
  auto sphere = [](bool closest) {
    return [closest](Reader& in, Writer& out) {
      const Sphere s = sphere_from(in);
      answer_query(s, in, out, [&](const Ray& r, Intersection* hit) {
        return closest ? s.intersect(r, hit) : s.has_intersection(r);
      });
    };
  };
  link.on(Call::SphereHas, sphere(false));
  link.on(Call::SphereIntersect, sphere(true));
}

}  // namespace pt::boundary
