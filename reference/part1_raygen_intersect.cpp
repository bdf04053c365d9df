// Part 1 reference: camera rays, pixel sampling, triangle and sphere hits.
#include <cmath>
#include <utility>

#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "render/pathtracer.h"
#include "scene/camera.h"

namespace pt {

// P1T1
Ray Camera::generate_ray(double x, double y) const {
  // Image [0,1]^2 -> sensor at z = -1 spanning +-tan(fov/2) -> world.
  Vec3 sensor((2.0 * x - 1.0) * std::tan(glm::radians(hfov) / 2.0), (2.0 * y - 1.0) * std::tan(glm::radians(vfov) / 2.0),
              -1.0);
  Ray r(pos, glm::normalize(c2w * sensor));
  r.min_t = near_clip;
  r.max_t = far_clip;
  return r;
}

// P1T2
PixelEstimate PathTracer::raytrace_pixel(int x, int y, Rng& rng) const {
  const int n = settings.ns_aa;
  Spectrum sum(0.0);
  for (int i = 0; i < n; ++i) {
    Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2();
    Ray r = camera->generate_ray((x + u.x) / settings.width, (y + u.y) / settings.height);
    sum += est_radiance_global_illumination(r, rng);
  }
  return {sum / double(n), n};
}

// P1T3. Watertight ray-triangle intersection (Woop, Benthin and Wald,
// "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013), in double
// precision. The ray is made the z axis of a sheared frame; a vertex's sheared
// coordinates depend only on the vertex and the ray, and the edge function of
// an edge is the same two products of its two vertices' coordinates in either
// triangle that shares it, subtracted in the opposite order: exactly the
// negative. A ray through an edge is therefore inside one of the two
// triangles or exactly on the edge of both, never outside both. (Moller-
// Trumbore computes each weight from the whole triangle, rounded differently
// in each: 5,198 of 68,583 rays aimed at the diagonals of random quads slip
// through it, none through this; tests/framework/test_watertight.cpp.)
// handouts/part1.md section 3 has the proof sketch.
namespace {
struct TriangleHit {
  double t, b0, b1, b2;  // weights of p1, p2, p3
};

bool watertight(const Ray& r, const Vec3& p1, const Vec3& p2, const Vec3& p3, TriangleHit* hit) {
  // The dominant axis of d becomes z; x and y follow it cyclically, swapped
  // when d points down that axis, so that the triangle's winding is kept.
  const Vec3 ad = glm::abs(r.d);
  const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (r.d[kz] < 0.0) std::swap(kx, ky);
  const double sx = r.d[kx] / r.d[kz], sy = r.d[ky] / r.d[kz], sz = 1.0 / r.d[kz];
  // Vertices relative to the origin, sheared so that the ray runs along z.
  const Vec3 a = p1 - r.o, b = p2 - r.o, c = p3 - r.o;
  const double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
  const double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
  const double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
  // Edge functions: twice the signed area the ray sees each edge span, i.e.
  // the unnormalised weight of the opposite vertex.
  const double u = cx * by - cy * bx;  // edge p2-p3: weight of p1
  const double v = ax * cy - ay * cx;  // edge p3-p1: weight of p2
  const double w = bx * ay - by * ax;  // edge p1-p2: weight of p3
  // Inside (edges included) when no two have strictly opposite signs; either
  // winding, so both faces are hit.
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
  const double det = u + v + w;
  if (det == 0.0) return false;  // ray in the triangle's plane, or a degenerate triangle
  const double t = (u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz])) / det;
  // Written so that NaN (a zero direction, infinite vertices) is never a hit.
  if (!(t >= r.min_t && t <= r.max_t)) return false;
  *hit = {t, u / det, v / det, w / det};
  return true;
}
}  // namespace

bool Triangle::has_intersection(const Ray& r) const {
  TriangleHit hit;
  return watertight(r, p1(), p2(), p3(), &hit);
}

bool Triangle::intersect(const Ray& r, Intersection* isect) const {
  TriangleHit hit;
  if (!watertight(r, p1(), p2(), p3(), &hit)) return false;
  r.max_t = hit.t;
  isect->t = hit.t;
  isect->barycentric = Vec3(hit.b0, hit.b1, hit.b2);
  isect->n = glm::normalize(hit.b0 * n1() + hit.b1 * n2() + hit.b2 * n3());
  isect->primitive = this;
  isect->bsdf = get_bsdf();
  return true;
}

// P1T4
bool Sphere::test(const Ray& ray, double& t1, double& t2) const {
  Vec3 oc = ray.o - o;
  double a = glm::dot(ray.d, ray.d);
  double b = 2.0 * glm::dot(oc, ray.d);
  double c = glm::dot(oc, oc) - r2;
  double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return false;
  // The textbook formula loses the small root to cancellation when |b| is
  // close to sqrt(disc); q never cancels, and the roots are q/a and c/q.
  double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) {
    t1 = t2 = 0.0;  // origin on the sphere, ray tangent to it
    return true;
  }
  t1 = q / a;
  t2 = c / q;
  if (t1 > t2) std::swap(t1, t2);
  return true;
}

namespace {
// The nearest root of the sphere inside the ray's t range, if any.
bool nearest_root(const Sphere& s, const Ray& ray, double* t) {
  double t1, t2;
  if (!s.test(ray, t1, t2)) return false;
  if (t1 >= ray.min_t && t1 <= ray.max_t) {
    *t = t1;
    return true;
  }
  if (t2 >= ray.min_t && t2 <= ray.max_t) {
    *t = t2;
    return true;
  }
  return false;
}
}  // namespace

bool Sphere::has_intersection(const Ray& ray) const {
  double t;
  return nearest_root(*this, ray, &t);
}

bool Sphere::intersect(const Ray& ray, Intersection* isect) const {
  double t;
  if (!nearest_root(*this, ray, &t)) return false;
  ray.max_t = t;
  isect->t = t;
  isect->n = glm::normalize(ray.at(t) - o);
  isect->barycentric = Vec3(0.0);
  isect->primitive = this;
  isect->bsdf = get_bsdf();
  return true;
}

}  // namespace pt
