#pragma once
// Wavefront OBJ meshes for the scene loader (through tinyobjloader).
#include <string>
#include <vector>

#include "core/vec.h"
#include "geometry/mesh.h"

namespace pt {

// Object-to-world placement of a mesh: scale, then rotate, then translate.
struct MeshTransform {
  Vec3 scale{1.0};
  Vec3 axis{0.0, 1.0, 0.0};  // rotation axis (any length but zero)
  double degrees = 0.0;      // counter-clockwise looking down the axis
  Vec3 translate{0.0};

  Vec3 apply_to_point(const Vec3& p) const;
  // Normals take the inverse transpose of the linear part, so they stay
  // perpendicular to the surface under non-uniform scale. Returns unit length.
  Vec3 apply_to_normal(const Vec3& n) const;
};

// Reads `path` as one triangle mesh in world space: polygons triangulated, all
// objects and groups merged, `transform` applied. Keeps the file's normals when
// every face corner has one (a vertex is split where its corners disagree);
// otherwise leaves `normals` empty for Scene::add_mesh to compute.
// Throws SceneError "path: ..." when the file cannot be read, is larger than
// kMaxMeshFileBytes, does not parse, refers to missing vertices or has no
// triangles, and "path:LINE: ..." at a line tinyobjloader would misread
// (obj_text_check.h: NaN, malformed numbers or indices, huge faces). Appends
// to `warnings` what it ignores (materials, lines and points, degenerate
// faces), each message starting with the path.
Mesh load_obj(const std::string& path, const MeshTransform& transform, std::vector<std::string>* warnings);

}  // namespace pt
