#include "geometry/triangulate.h"

#include <cmath>
#include <numeric>

namespace pt {

namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

// Whether p lies in the counter-clockwise triangle abc, edges included (a
// corner on an ear's edge would make the ear cut the polygon).
bool in_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross2(b - a, p - a) >= 0.0 && cross2(c - b, p - b) >= 0.0 && cross2(a - c, p - c) >= 0.0;
}

}  // namespace

std::vector<std::array<uint32_t, 3>> triangulate_polygon(const std::vector<Vec3>& corners) {
  const size_t n = corners.size();
  std::vector<std::array<uint32_t, 3>> out;
  if (n < 3) return out;
  out.reserve(n - 2);
  std::vector<uint32_t> left(n);
  std::iota(left.begin(), left.end(), 0u);
  auto fan = [&] {
    for (size_t i = 1; i + 1 < left.size(); ++i) out.push_back({left[0], left[i], left[i + 1]});
    return out;
  };
  if (n == 3 || n > kMaxEarClippingCorners) return fan();

  // Newell's normal: robust for non-planar and concave polygons; it points
  // to the side from which the corners run counter-clockwise.
  Vec3 normal(0.0);
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = corners[i];
    const Vec3& b = corners[(i + 1) % n];
    normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  Vec3 size = glm::abs(normal);
  if (!is_finite(normal) || max_component(size) == 0.0) return fan();
  // Project along the normal's largest axis; (u, v, axis) is a cyclic order,
  // so the projection keeps the winding, mirrored when the normal points down
  // that axis so that the polygon always runs counter-clockwise in 2D.
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double flip = normal[axis] < 0.0 ? -1.0 : 1.0;
  std::vector<Vec2> p(n);
  for (size_t i = 0; i < n; ++i) p[i] = Vec2(corners[i][u], flip * corners[i][v]);

  while (left.size() > 3) {
    const size_t m = left.size();
    bool clipped = false;
    for (size_t k = 0; k < m && !clipped; ++k) {
      uint32_t a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
      if (cross2(p[b] - p[a], p[c] - p[b]) <= 0.0) continue;  // a reflex or flat corner is no ear
      bool empty = true;
      for (uint32_t j : left)
        if (j != a && j != b && j != c && in_triangle(p[j], p[a], p[b], p[c])) {
          empty = false;
          break;
        }
      if (!empty) continue;
      out.push_back({a, b, c});
      left.erase(left.begin() + std::ptrdiff_t(k));
      clipped = true;
    }
    if (!clipped) return fan();  // self-intersecting or degenerate: no ear left
  }
  out.push_back({left[0], left[1], left[2]});
  return out;
}

}  // namespace pt
