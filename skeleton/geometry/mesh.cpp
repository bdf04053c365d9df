#include "geometry/mesh.h"

namespace pt {

void Mesh::compute_vertex_normals() {
  normals.assign(positions.size(), Vec3(0.0));
  for (const auto& f : faces) {
    // The unnormalised cross product is twice the area times the unit normal.
    Vec3 n = glm::cross(positions[f[1]] - positions[f[0]], positions[f[2]] - positions[f[0]]);
    for (uint32_t i : f) normals[i] += n;
  }
  for (Vec3& n : normals) {
    double len = glm::length(n);
    n = len > 0.0 ? n / len : Vec3(0.0, 0.0, 1.0);
  }
}

}  // namespace pt
