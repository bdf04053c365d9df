#include "support/part3_closed_forms.h"

#include <cmath>

namespace pt::test {

Polygon parallelogram(const Vec3& c, const Vec3& ex, const Vec3& ey) {
  const Vec3 hx = 0.5 * ex, hy = 0.5 * ey;
  return {c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy};
}

Polygon clip_polygon(const Polygon& poly, const Vec3& point, const Vec3& normal) {
  Polygon out;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = poly[i];
    const Vec3& b = poly[(i + 1) % n];
    const double da = glm::dot(a - point, normal), db = glm::dot(b - point, normal);
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));  // the edge crosses the plane
  }
  return out;
}

Polygon visible_past_edge(const Polygon& light, const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& inside) {
  Vec3 m = glm::cross(b - a, a - p);
  if (glm::dot(m, inside - p) > 0.0) m = -m;
  return clip_polygon(light, p, m);
}

double polygon_irradiance(const Vec3& p, const Vec3& n, const Polygon& poly, double radiance) {
  const Polygon clipped = clip_polygon(poly, p, n);
  if (clipped.size() < 3) return 0.0;
  std::vector<Vec3> v;
  for (const Vec3& q : clipped) {
    const Vec3 d = q - p;
    const double len = glm::length(d);
    if (len > 0.0) v.push_back(d / len);
  }
  double sum = 0.0;
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = v[i];
    const Vec3& b = v[(i + 1) % v.size()];
    const Vec3 c = glm::cross(a, b);
    const double s = glm::length(c);
    if (s == 0.0) continue;  // a repeated vertex: the edge has no length
    const double theta = std::atan2(s, glm::dot(a, b));
    sum += theta * glm::dot(n, c / s);
  }
  return 0.5 * radiance * std::abs(sum);
}

double parallelogram_irradiance(const Vec3& p, const Vec3& n, const Vec3& c, const Vec3& ex, const Vec3& ey,
                                double radiance) {
  if (glm::dot(p - c, glm::cross(ex, ey)) <= 0.0) return 0.0;  // behind a one-sided emitter
  return polygon_irradiance(p, n, parallelogram(c, ex, ey), radiance);
}

double parallelogram_irradiance_numerical(const Vec3& p, const Vec3& n, const Vec3& c, const Vec3& ex, const Vec3& ey,
                                          double radiance, int res, const std::function<bool(const Vec3& q)>& visible) {
  const Vec3 ln = glm::normalize(glm::cross(ex, ey));
  const double dA = glm::length(glm::cross(ex, ey)) / (double(res) * res);
  double sum = 0.0;
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      const Vec3 q = c + ((i + 0.5) / res - 0.5) * ex + ((j + 0.5) / res - 0.5) * ey;
      const Vec3 d = q - p;
      const double r2 = glm::dot(d, d), r = std::sqrt(r2);
      const double cos_p = glm::dot(n, d) / r, cos_l = -glm::dot(ln, d) / r;
      if (cos_p > 0.0 && cos_l > 0.0 && (!visible || visible(q))) sum += cos_p * cos_l / r2;
    }
  return radiance * sum * dA;
}

}  // namespace pt::test
