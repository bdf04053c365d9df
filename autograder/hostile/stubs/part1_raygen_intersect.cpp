// Part 1's stubs as the release ships them, without their comments: the base
// of the hostile cases that are an attack in an otherwise untouched submission
// (README.md beside this folder). Frozen here so that a case never changes
// when tasks/, the student's file, does.
#include <cmath>

#include "core/not_implemented.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "render/pathtracer.h"
#include "scene/camera.h"

namespace pt {

Ray Camera::generate_ray(double x, double y) const {
  throw NotImplemented("P1T1 Camera::generate_ray");
}

PixelEstimate PathTracer::raytrace_pixel(int x, int y, Rng& rng) const {
  throw NotImplemented("P1T2 PathTracer::raytrace_pixel");
}

bool Triangle::has_intersection(const Ray& r) const {
  throw NotImplemented("P1T3 Triangle::has_intersection");
}

bool Triangle::intersect(const Ray& r, Intersection* isect) const {
  throw NotImplemented("P1T3 Triangle::intersect");
}

bool Sphere::test(const Ray& ray, double& t1, double& t2) const {
  throw NotImplemented("P1T4 Sphere::test");
}

bool Sphere::has_intersection(const Ray& ray) const {
  throw NotImplemented("P1T4 Sphere::has_intersection");
}

bool Sphere::intersect(const Ray& ray, Intersection* isect) const {
  throw NotImplemented("P1T4 Sphere::intersect");
}

}  // namespace pt
