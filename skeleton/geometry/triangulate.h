#pragma once
// Splitting an imported polygon into triangles.
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace pt {

// Polygons with more corners than this are fan-triangulated (ear clipping
// costs O(n^3) here); a fan is right for convex polygons only.
constexpr size_t kMaxEarClippingCorners = 64;

// Splits the polygon with these corners (in order, planar or nearly so) into
// n - 2 triangles, returned as triples of corner indices with the polygon's
// winding. Ear clipping in the polygon's plane, so concave polygons are split
// correctly; a self-intersecting or degenerate remainder, and polygons with
// more than kMaxEarClippingCorners corners, get a fan from the first corner.
std::vector<std::array<uint32_t, 3>> triangulate_polygon(const std::vector<Vec3>& corners);

}  // namespace pt
