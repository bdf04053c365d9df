// Part 1 reference: camera rays, pixel sampling, triangle and sphere hits.
#include <cmath>

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

// P1T3. Moller-Trumbore: solve o + t d = (1 - b1 - b2) p1 + b1 p2 + b2 p3 by
// Cramer's rule with the shared cross products s1 and s2.
namespace {
struct TriangleHit {
  double t, b1, b2;
};

bool moller_trumbore(const Ray& r, const Vec3& p1, const Vec3& p2, const Vec3& p3, TriangleHit* hit) {
  Vec3 e1 = p2 - p1, e2 = p3 - p1, s = r.o - p1;
  Vec3 s1 = glm::cross(r.d, e2), s2 = glm::cross(s, e1);
  double det = glm::dot(s1, e1);
  if (det == 0.0 || !std::isfinite(det)) return false;  // ray parallel to the plane, or a degenerate triangle
  double inv = 1.0 / det;
  double t = glm::dot(s2, e2) * inv;
  double b1 = glm::dot(s1, s) * inv;
  double b2 = glm::dot(s2, r.d) * inv;
  // Written so that NaN fails every comparison and so never counts as a hit.
  if (!(b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0 && t >= r.min_t && t <= r.max_t)) return false;
  *hit = {t, b1, b2};
  return true;
}
}  // namespace

bool Triangle::has_intersection(const Ray& r) const {
  TriangleHit hit;
  return moller_trumbore(r, p1(), p2(), p3(), &hit);
}

bool Triangle::intersect(const Ray& r, Intersection* isect) const {
  TriangleHit hit;
  if (!moller_trumbore(r, p1(), p2(), p3(), &hit)) return false;
  double b0 = 1.0 - hit.b1 - hit.b2;
  r.max_t = hit.t;
  isect->t = hit.t;
  isect->barycentric = Vec3(b0, hit.b1, hit.b2);
  isect->n = glm::normalize(b0 * n1() + hit.b1 * n2() + hit.b2 * n3());
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
