// The verifier's Part 1: each task function asks the worker (README.md beside
// this file). What the tests inspect comes back: the ray, the pixel's
// estimate and the generator's state, the hit and the ray's shrunk range.
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "hit_codec.h"
#include "render/pathtracer.h"
#include "scene/camera.h"
#include "verifier_link.h"

namespace pt {
namespace {

using boundary::Call;
using boundary::call_worker;
using boundary::Reader;
using boundary::Writer;

// "Something else" in an answer is what the hit record pointed at before the
// call, when that was something else too; otherwise a stand-in.
boundary::HitSide side_of(const Primitive* asked, const Intersection* before) {
  const BSDF* own = asked->get_bsdf();
  const bool prim_elsewhere = before && before->primitive && before->primitive != asked;
  const bool bsdf_elsewhere = before && before->bsdf && before->bsdf != own;
  return {asked, prim_elsewhere ? before->primitive : boundary::elsewhere_primitive(), own,
          bsdf_elsewhere ? before->bsdf : boundary::elsewhere_bsdf()};
}

// A query's answer: hit or not, the ray's range after it, and the hit record.
bool take_answer(const std::string& answer, const Ray& r, Intersection* isect, const boundary::HitSide& side) {
  return boundary::read_answer([&] {
    Reader out(answer);
    const bool hit = out.get<uint8_t>() != 0;
    r.min_t = out.get<double>();
    r.max_t = out.get<double>();
    if (isect) boundary::get_hit(out, *isect, side);
    out.finish();
    return hit;
  });
}

Writer triangle_query(const Triangle& t, const Ray& r, const Intersection* isect, const boundary::HitSide& side) {
  Writer in;
  in.put(t.p1()).put(t.p2()).put(t.p3()).put(t.n1()).put(t.n2()).put(t.n3());
  in.put(static_cast<uint8_t>(t.get_bsdf() != nullptr)).put(r).put(static_cast<uint8_t>(isect != nullptr));
  if (isect) boundary::put_hit(in, *isect, side);
  return in;
}

Writer sphere_query(const Sphere& s, const Ray& r, const Intersection* isect, const boundary::HitSide& side) {
  Writer in;
  in.put(s.o).put(s.r).put(s.r2).put(static_cast<uint8_t>(s.get_bsdf() != nullptr)).put(r);
  in.put(static_cast<uint8_t>(isect != nullptr));
  if (isect) boundary::put_hit(in, *isect, side);
  return in;
}

}  // namespace

Ray Camera::generate_ray(double x, double y) const {
  Writer in;
  in.put(*this).put(x).put(y);
  const std::string answer = call_worker(Call::GenerateRay, in);
  return boundary::read_answer([&] {
    Reader out(answer);
    const auto ray = out.get<Ray>();
    out.finish();
    return ray;
  });
}

PixelEstimate PathTracer::raytrace_pixel(int x, int y, Rng& rng) const {
  return boundary::ask_pixel(Call::RaytracePixel, "PathTracer::raytrace_pixel", *this, x, y, rng);
}

bool Triangle::has_intersection(const Ray& r) const {
  const auto side = side_of(this, nullptr);
  return take_answer(call_worker(Call::TriangleHas, triangle_query(*this, r, nullptr, side)), r, nullptr, side);
}

bool Triangle::intersect(const Ray& r, Intersection* isect) const {
  const auto side = side_of(this, isect);
  return take_answer(call_worker(Call::TriangleIntersect, triangle_query(*this, r, isect, side)), r, isect, side);
}

bool Sphere::test(const Ray& ray, double& t1, double& t2) const {
  Writer in = sphere_query(*this, ray, nullptr, side_of(this, nullptr));
  in.put(t1).put(t2);
  const std::string answer = call_worker(Call::SphereTest, in);
  return boundary::read_answer([&] {
    Reader out(answer);
    const bool roots = out.get<uint8_t>() != 0;
    out.get(t1);
    out.get(t2);
    out.finish();
    return roots;
  });
}

bool Sphere::has_intersection(const Ray& ray) const {
  const auto side = side_of(this, nullptr);
  return take_answer(call_worker(Call::SphereHas, sphere_query(*this, ray, nullptr, side)), ray, nullptr, side);
}

bool Sphere::intersect(const Ray& ray, Intersection* isect) const {
  const auto side = side_of(this, isect);
  return take_answer(call_worker(Call::SphereIntersect, sphere_query(*this, ray, isect, side)), ray, isect, side);
}

}  // namespace pt
