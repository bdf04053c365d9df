#include "io/obj_loader.h"

#include <map>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <tiny_obj_loader.h>

#include "io/input_file.h"
#include "io/obj_text_check.h"
#include "io/scene_loader.h"

namespace pt {

namespace {

// Reads no .mtl file, only notes that one was asked for: the framework has its
// own materials and says so in a warning rather than opening files it ignores.
class IgnoreMaterials : public tinyobj::MaterialReader {
 public:
  std::vector<std::string> libraries;
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>*, std::map<std::string, int>*,
                  std::string*, std::string*) override {
    libraries.push_back(name);
    return true;
  }
};

// An istream over a string, without copying it (std::istringstream would).
class StringStream : private std::streambuf, public std::istream {
 public:
  explicit StringStream(const std::string& s) : std::istream(this) {
    char* p = const_cast<char*>(s.data());  // read only: the get area is never written
    setg(p, p, p + s.size());
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    // tinyobjloader ends some messages with "\n." (glued to the next message)
    // or "\n\n".
    size_t start = line.find_first_not_of('.');
    if (start != std::string::npos) out.push_back(line.substr(start));
  }
  return out;
}

Mat3 linear_part(const MeshTransform& t) {
  Mat3 rotate(glm::rotate(Mat4(1.0), glm::radians(t.degrees), glm::normalize(t.axis)));
  Mat3 scale(1.0);
  for (int i = 0; i < 3; ++i) scale[i][i] = t.scale[i];
  return rotate * scale;
}

}  // namespace

Vec3 MeshTransform::apply_to_point(const Vec3& p) const { return linear_part(*this) * p + translate; }

Vec3 MeshTransform::apply_to_normal(const Vec3& n) const {
  return glm::normalize(glm::transpose(glm::inverse(linear_part(*this))) * n);
}

Mesh load_obj(const std::string& path, const MeshTransform& transform, std::vector<std::string>* warnings) {
  const std::string text = read_input_file(path, kMaxMeshFileBytes, "a mesh file");
  check_obj_text(text, path);
  StringStream in(text);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  IgnoreMaterials mtl;
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &mtl, /*triangulate=*/true,
                        /*default_vcols_fallback=*/false)) {
    auto lines = lines_of(err);
    throw SceneError(path + ": cannot parse OBJ" + (lines.empty() ? "" : ": " + lines.front()));
  }

  // tinyobjloader only warns about indices past the end (and skips such
  // polygons): fail instead, since the file is broken. Faces with fewer than
  // three vertices it drops, one warning each; we report them once, counted.
  bool uses_materials = !mtl.libraries.empty();
  std::map<std::string, int> repeated;
  std::vector<std::string> order;
  for (const std::string& line : lines_of(warn)) {
    if (line.find("not found in .mtl") != std::string::npos) {
      uses_materials = true;
      continue;
    }
    if (line.find("invalid vertex index") != std::string::npos)
      throw SceneError(path + ": a face refers to a vertex that the file does not have");
    if (line.find("indices out of bounds") != std::string::npos && line.find("texcoord") == std::string::npos)
      continue;  // checked below
    std::string what = line.rfind("Degenerated face", 0) == 0 ? "faces with fewer than 3 vertices skipped" : line;
    if (repeated[what]++ == 0) order.push_back(what);
  }
  for (const auto& what : order)
    warnings->push_back(path + ": " + what + (repeated[what] > 1 ? " (" + std::to_string(repeated[what]) + " times)" : ""));
  if (uses_materials)
    warnings->push_back(path + ": OBJ materials (mtllib/usemtl) are ignored; the whole mesh uses the scene's material");

  const size_t n_positions = attrib.vertices.size() / 3, n_normals = attrib.normals.size() / 3;
  size_t n_corners = 0, lines = 0, points = 0;
  bool all_normals = true;
  for (const auto& s : shapes) {
    n_corners += s.mesh.indices.size();
    lines += s.lines.num_line_vertices.size();
    points += s.points.indices.size();
    for (const auto& idx : s.mesh.indices) all_normals = all_normals && idx.normal_index >= 0;
  }
  if (lines + points > 0)
    warnings->push_back(path + ": " + std::to_string(lines) + " line(s) and " + std::to_string(points) +
                        " point(s) ignored: only faces are rendered");
  if (n_corners == 0) throw SceneError(path + ": no triangles (an empty mesh)");

  auto position = [&](int i) {
    if (i < 0 || size_t(i) >= n_positions)
      throw SceneError(path + ": a face refers to vertex " + std::to_string(i + 1) + ", but the file has " +
                       std::to_string(n_positions));
    Vec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    if (!is_finite(p)) throw SceneError(path + ": vertex " + std::to_string(i + 1) + " is not finite");
    return transform.apply_to_point(p);
  };
  auto normal = [&](int i) {
    if (size_t(i) >= n_normals)
      throw SceneError(path + ": a face refers to normal " + std::to_string(i + 1) + ", but the file has " +
                       std::to_string(n_normals));
    Vec3 n(attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]);
    if (!is_finite(n) || glm::length(n) == 0.0)
      throw SceneError(path + ": normal " + std::to_string(i + 1) + " is zero or not finite");
    return transform.apply_to_normal(n);
  };

  Mesh mesh;
  mesh.name = path;
  // One mesh vertex per distinct (position, normal) pair, so that a position
  // whose corners carry different normals (a crease) keeps them all.
  std::map<std::pair<int, int>, uint32_t> vertex_of;
  for (const auto& s : shapes) {
    for (size_t c = 0; c + 2 < s.mesh.indices.size(); c += 3) {
      std::array<uint32_t, 3> face;
      for (int k = 0; k < 3; ++k) {
        const tinyobj::index_t& idx = s.mesh.indices[c + k];
        auto key = std::make_pair(idx.vertex_index, all_normals ? idx.normal_index : -1);
        auto [it, inserted] = vertex_of.emplace(key, uint32_t(mesh.positions.size()));
        if (inserted) {
          mesh.positions.push_back(position(idx.vertex_index));
          if (all_normals) mesh.normals.push_back(normal(idx.normal_index));
        }
        face[k] = it->second;
      }
      mesh.faces.push_back(face);
    }
  }
  return mesh;
}

}  // namespace pt
