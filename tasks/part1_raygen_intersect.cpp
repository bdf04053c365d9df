// Part 1: ray generation and scene intersection. See handouts/part1.md.
// Each function below is one task; replace its `throw` with your code.
#include <cmath>

#include "core/not_implemented.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "render/pathtracer.h"
#include "scene/camera.h"

namespace pt {

Ray Camera::generate_ray(double x, double y) const {
  // TODO(P1T1): map (x, y) in [0,1]^2 to the sensor plane z = -1 in camera
  // space (spanning +-tan(hfov/2) by +-tan(vfov/2); hfov and vfov are in
  // degrees), rotate by c2w, normalise. Origin: pos. t range: [near_clip, far_clip].
  throw NotImplemented("P1T1 Camera::generate_ray");
}

PixelEstimate PathTracer::raytrace_pixel(int x, int y, Rng& rng) const {
  // TODO(P1T2): average settings.ns_aa estimates of est_radiance_global_illumination
  // along camera rays through pixel (x, y) of a settings.width x settings.height
  // image: jittered with rng.uniform2() inside the pixel, or through its centre
  // when ns_aa == 1. Return the average and the number of samples taken.
  throw NotImplemented("P1T2 PathTracer::raytrace_pixel");
}

bool Triangle::has_intersection(const Ray& r) const {
  // TODO(P1T3): Moller-Trumbore; true when the ray hits inside the triangle
  // (edges included) at t in [r.min_t, r.max_t].
  throw NotImplemented("P1T3 Triangle::has_intersection");
}

bool Triangle::intersect(const Ray& r, Intersection* isect) const {
  // TODO(P1T3): as has_intersection; on a hit set r.max_t = t and fill isect:
  // t, barycentric (weights of p1, p2, p3), the unit normal interpolated from
  // n1(), n2(), n3() with those weights, primitive = this, bsdf = get_bsdf().
  throw NotImplemented("P1T3 Triangle::intersect");
}

bool Sphere::test(const Ray& ray, double& t1, double& t2) const {
  // TODO(P1T4): solve the quadratic for |ray.o + t ray.d - o|^2 = r2. Return
  // false when there is no real root; otherwise write both roots, t1 <= t2.
  throw NotImplemented("P1T4 Sphere::test");
}

bool Sphere::has_intersection(const Ray& ray) const {
  // TODO(P1T4): true when a root of test() lies in [ray.min_t, ray.max_t].
  throw NotImplemented("P1T4 Sphere::has_intersection");
}

bool Sphere::intersect(const Ray& ray, Intersection* isect) const {
  // TODO(P1T4): the nearest root in range (the far one when the origin is
  // inside); set ray.max_t, and fill isect with the outward unit normal.
  throw NotImplemented("P1T4 Sphere::intersect");
}

}  // namespace pt
