#pragma once
// Closed forms of direct lighting used by the Part 3 tests (and checked
// against brute-force integration in tests/framework/test_sampling_distributions.cpp).
#include <functional>
#include <vector>

#include "core/vec.h"

namespace pt::test {

using Polygon = std::vector<Vec3>;

// Corners of the parallelogram of Scene::add_quad / AreaLight (centre c,
// edges ex, ey), in the order c-ex/2-ey/2, c+ex/2-ey/2, c+ex/2+ey/2,
// c-ex/2+ey/2: counter-clockwise about cross(ex, ey), the emitting side.
Polygon parallelogram(const Vec3& c, const Vec3& ex, const Vec3& ey);

// The part of a convex planar polygon on the side dot(x - point, normal) >= 0
// (Sutherland-Hodgman against one plane). May return fewer than 3 vertices.
Polygon clip_polygon(const Polygon& poly, const Vec3& point, const Vec3& normal);

// The part of a light polygon that p sees past the straight edge a-b of an
// opaque occluder (`inside` is any point of the occluder off the edge): the
// polygon clipped by the plane through p and the edge, keeping the side away
// from the occluder. Valid when the occluder lies between p and the light and
// reaches past the light's cone everywhere but along that edge.
Polygon visible_past_edge(const Polygon& light, const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& inside);

// Irradiance E = integral of L cos(theta) d(omega) at p (unit normal n) from
// a convex polygon of uniform radiance L, all of it visible: the polygon is
// first clipped to the hemisphere of n, so the parts below p's horizon
// contribute nothing, then Lambert's formula (1760; Arvo 1994) for the clipped
// spherical polygon with unit vertex directions v_i:
//   E = (L / 2) | sum_i Theta_i  n . unit(v_i x v_{i+1}) |,
//   Theta_i = angle between v_i and v_{i+1}.
// Each term is the flux of the edge's great-circle "wedge"; the sum over a
// closed contour is the projected solid angle. Its sign says only whether the
// contour runs clockwise or counter-clockwise as seen from p, hence the
// absolute value (valid because the clipped polygon lies wholly in the upper
// hemisphere, where cos(theta) >= 0 everywhere).
double polygon_irradiance(const Vec3& p, const Vec3& n, const Polygon& poly, double radiance);

// A one-sided parallelogram emitter (the AreaLight of the framework, emitting
// towards cross(ex, ey)): zero when p is behind it or in its plane.
double parallelogram_irradiance(const Vec3& p, const Vec3& n, const Vec3& c, const Vec3& ex, const Vec3& ey,
                                double radiance);

// The same by brute force, to check the closed form: the area integral
//   E = integral over the light of L max(0, cos theta) cos(theta_light) / r^2 dA
// by the midpoint rule on res x res sub-rectangles, counting only the points
// q of the light for which visible(q) holds when it is given (a shadow ray).
double parallelogram_irradiance_numerical(const Vec3& p, const Vec3& n, const Vec3& c, const Vec3& ex, const Vec3& ey,
                                          double radiance, int res,
                                          const std::function<bool(const Vec3& q)>& visible = {});

}  // namespace pt::test
