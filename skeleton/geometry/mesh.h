#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/vec.h"

namespace pt {

class BSDF;

// An indexed triangle mesh in world space. Triangles refer to it by index, so
// a million-triangle mesh stores each vertex once.
struct Mesh {
  std::string name;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // per vertex, unit length; same size as positions
  std::vector<std::array<uint32_t, 3>> faces;
  const BSDF* bsdf = nullptr;

  // Fills `normals` with area-weighted averages of the face normals, for meshes
  // that come without them.
  void compute_vertex_normals();
};

}  // namespace pt
