#include "io/collada_mesh.h"

#include <cstring>
#include <map>
#include <unordered_map>

#include "geometry/triangulate.h"

namespace pt {

namespace {

// Inputs of one primitive share the index tuples of <p>; offsets beyond this
// are no real file's and would only inflate the tuple.
constexpr uint64_t kMaxInputOffset = 63;

// A <source> read through its accessor: element i is `components` numbers
// starting at values[offset + i * stride].
struct Source {
  std::vector<double> values;
  size_t count = 0, stride = 0, offset = 0;
  Vec3 vec3(size_t i) const {
    size_t k = offset + i * stride;
    return Vec3(values[k], values[k + 1], values[k + 2]);
  }
};

// A source and the element whose indices refer to it (for messages).
struct Indexed {
  const Source* source = nullptr;
  uint32_t offset = 0;
  std::string what;  // "positions of <vertices>", ...
};

// The index tuples of a primitive's polygons (or strips, or fans), flat:
// polygon k is index[start[k] .. start[k + 1]).
struct Polygons {
  std::vector<uint32_t> index;
  std::vector<size_t> start{0};
  size_t size() const { return start.size() - 1; }
  void add(const std::vector<uint32_t>& p) {
    index.insert(index.end(), p.begin(), p.end());
    start.push_back(index.size());
  }
};

class MeshReader {
 public:
  MeshReader(ColladaDocument& doc, XmlNode mesh) : doc_(doc), mesh_(mesh) {}

  std::vector<ColladaMeshPart> read() {
    std::vector<ColladaMeshPart> parts;
    size_t lines = 0;
    for (XmlNode e : mesh_.children()) {
      if (e.type() != pugi::node_element) continue;
      const char* name = e.name();
      if (is(name, "triangles") || is(name, "polylist") || is(name, "polygons") || is(name, "trifans") ||
          is(name, "tristrips")) {
        parts.push_back(read_part(e));
      } else if (is(name, "lines") || is(name, "linestrips")) {
        ++lines;
      } else if (!is(name, "source") && !is(name, "vertices") && !is(name, "extra")) {
        doc_.warn(e, "unknown element in <mesh> ignored");
      }
    }
    if (lines > 0)
      doc_.warn(mesh_, std::to_string(lines) + " <lines>/<linestrips> element(s) ignored: only surfaces are rendered");
    return parts;
  }

 private:
  ColladaDocument& doc_;
  XmlNode mesh_;
  std::map<const void*, Source> sources_;  // by <source> element, read once

  static bool is(const char* a, const char* b) { return std::strcmp(a, b) == 0; }

  // The <source> that input's `source` attribute names, with at least
  // `components` numbers per element.
  const Source& source(XmlNode input, size_t components) {
    XmlNode src = doc_.resolve(input, "source", "source");
    auto it = sources_.find(src.internal_object());
    if (it != sources_.end()) {
      if (it->second.stride < components) fail_stride(src, it->second.stride, components);
      return it->second;
    }
    Source s;
    XmlNode accessor = src.child("technique_common").child("accessor");
    XmlNode array = accessor ? doc_.resolve(accessor, "source", "float_array") : src.child("float_array");
    if (!array) doc_.fail(src, "has no <float_array> (only float sources are supported for positions, normals and texture coordinates)");
    s.values = doc_.numbers(array);
    uint64_t declared = doc_.integer_attribute(array, "count", s.values.size());
    if (declared != s.values.size())
      doc_.fail(array, "count=\"" + std::to_string(declared) + "\" but it holds " + std::to_string(s.values.size()) +
                           " numbers");
    if (accessor) {
      s.count = doc_.integer_attribute(accessor, "count");
      s.stride = doc_.integer_attribute(accessor, "stride", 1);
      s.offset = doc_.integer_attribute(accessor, "offset", 0);
      if (s.stride < components) fail_stride(accessor, s.stride, components);
      // All factors are below 2^32, so none of this overflows 64 bits.
      uint64_t needed = s.count == 0 ? 0 : uint64_t(s.offset) + uint64_t(s.count - 1) * s.stride + components;
      if (needed > s.values.size())
        doc_.fail(accessor, "count=\"" + std::to_string(s.count) + "\" with stride " + std::to_string(s.stride) +
                                " and offset " + std::to_string(s.offset) + " needs " + std::to_string(needed) +
                                " numbers, the array holds " + std::to_string(s.values.size()));
    } else {
      s.stride = components;
      s.count = s.values.size() / components;
      if (s.values.size() % components != 0)
        doc_.fail(array, "holds " + std::to_string(s.values.size()) + " numbers, not a multiple of " +
                             std::to_string(components) + " (and the <source> has no <accessor> to say how to read it)");
    }
    return sources_.emplace(src.internal_object(), std::move(s)).first->second;
  }

  [[noreturn]] void fail_stride(XmlNode at, size_t stride, size_t components) const {
    doc_.fail(at, "stride " + std::to_string(stride) + " is too small: this source must give " +
                      std::to_string(components) + " numbers per element");
  }

  ColladaMeshPart read_part(XmlNode e) {
    ColladaMeshPart part;
    part.element = e;
    part.material = e.attribute("material").value();

    // Inputs. VERTEX goes through <vertices> (positions, and maybe per-vertex
    // normals); a NORMAL input of the primitive itself takes precedence.
    Indexed position, normal, vertex_normal;
    std::vector<Indexed> texcoords;
    bool has_vertex = false;
    uint64_t stride = 0;
    for (XmlNode input : e.children("input")) {
      std::string semantic = input.attribute("semantic").value();
      uint64_t offset = doc_.integer_attribute(input, "offset");
      if (offset > kMaxInputOffset) doc_.fail(input, "offset " + std::to_string(offset) + " is too large (at most 63)");
      stride = std::max(stride, offset + 1);
      if (semantic == "VERTEX" && !has_vertex) {
        has_vertex = true;
        XmlNode vertices = doc_.resolve(input, "source", "vertices");
        for (XmlNode vi : vertices.children("input")) {
          std::string vs = vi.attribute("semantic").value();
          if (vs == "POSITION" && !position.source) position = {&source(vi, 3), uint32_t(offset), "positions"};
          if (vs == "NORMAL" && !vertex_normal.source) vertex_normal = {&source(vi, 3), uint32_t(offset), "normals"};
        }
        if (!position.source) doc_.fail(vertices, "has no POSITION input");
      } else if (semantic == "NORMAL" && !normal.source) {
        normal = {&source(input, 3), uint32_t(offset), "normals"};
      } else if (semantic == "TEXCOORD") {
        texcoords.push_back({&source(input, 1), uint32_t(offset), "texture coordinates"});
      }
    }
    if (!has_vertex) doc_.fail(e, "has no VERTEX input");
    // Per-vertex normals share the position index.
    const bool per_corner_normals = normal.source != nullptr;
    if (!per_corner_normals) normal = vertex_normal;

    const Polygons polygons = polygon_indices(e, stride);
    const std::vector<uint32_t>& index = polygons.index;

    // Every index must be in range before any is used.
    std::vector<Indexed> checked = texcoords;
    checked.push_back(position);
    if (per_corner_normals) checked.push_back(normal);
    for (const Indexed& in : checked)
      for (size_t c = in.offset; c < index.size(); c += stride)
        if (index[c] >= in.source->count)
          doc_.fail(e, "index " + std::to_string(index[c]) + " at offset " + std::to_string(in.offset) +
                           " is out of range: the " + in.what + " source has " + std::to_string(in.source->count) +
                           " elements");
    if (!per_corner_normals && normal.source && normal.source->count < position.source->count)
      doc_.fail(e, "<vertices> has " + std::to_string(position.source->count) + " positions but only " +
                       std::to_string(normal.source->count) + " normals");

    // One mesh vertex per distinct (position, normal) pair.
    std::unordered_map<uint64_t, uint32_t> vertex_of;
    const uint64_t normal_range = normal.source ? uint64_t(normal.source->count) + 1 : 1;
    size_t base = 0;  // where the current polygon's tuples start
    auto vertex = [&](size_t corner) {
      uint32_t pi = index[base + corner * stride + position.offset];
      uint32_t ni = !normal.source ? 0 : per_corner_normals ? index[base + corner * stride + normal.offset] : pi;
      auto [it, inserted] = vertex_of.emplace(uint64_t(pi) * normal_range + ni, uint32_t(part.positions.size()));
      if (inserted) {
        part.positions.push_back(position.source->vec3(pi));
        if (normal.source) part.normals.push_back(normal.source->vec3(ni));
      }
      return it->second;
    };

    const bool strips = std::strcmp(e.name(), "tristrips") == 0, fans = std::strcmp(e.name(), "trifans") == 0;
    size_t too_small = 0, fanned = 0;
    std::vector<Vec3> corners;
    for (size_t k = 0; k < polygons.size(); ++k) {
      base = polygons.start[k];
      const size_t n = (polygons.start[k + 1] - base) / stride;
      if (n < 3) {
        ++too_small;
        continue;
      }
      if (strips || fans) {
        // A fan turns around corner 0; a strip alternates its winding.
        for (size_t i = 0; i + 2 < n; ++i) {
          if (fans) part.faces.push_back({vertex(0), vertex(i + 1), vertex(i + 2)});
          else if (i % 2 == 0) part.faces.push_back({vertex(i), vertex(i + 1), vertex(i + 2)});
          else part.faces.push_back({vertex(i + 1), vertex(i), vertex(i + 2)});
        }
        continue;
      }
      corners.clear();
      for (size_t i = 0; i < n; ++i) corners.push_back(position.source->vec3(index[base + i * stride + position.offset]));
      fanned += n > kMaxEarClippingCorners;
      for (const auto& t : triangulate_polygon(corners)) part.faces.push_back({vertex(t[0]), vertex(t[1]), vertex(t[2])});
    }
    if (too_small > 0)
      doc_.warn(e, std::to_string(too_small) + " polygon(s) with fewer than 3 corners skipped");
    if (fanned > 0)
      doc_.warn(e, std::to_string(fanned) + " polygon(s) with more than " + std::to_string(kMaxEarClippingCorners) +
                       " corners split as a fan (right for convex polygons only)");
    for (const Vec3& n : part.normals)
      if (glm::length(n) == 0.0) {
        doc_.warn(e, "has zero-length normals: area-weighted vertex normals are computed instead");
        part.normals.clear();
        break;
      }
    return part;
  }

  // The index tuples of each polygon (strip, fan) of e, checked against the
  // counts the element declares.
  Polygons polygon_indices(XmlNode e, uint64_t stride) {
    const std::string name = e.name();
    const uint64_t count = doc_.integer_attribute(e, "count");
    Polygons out;
    if (name == "triangles" || name == "polylist") {
      out.index = e.child("p") ? doc_.integers(e.child("p")) : std::vector<uint32_t>{};
      const size_t n = out.index.size();
      std::vector<uint32_t> sizes;
      if (name == "triangles") {
        if (n != count * 3 * stride)  // below 2^41: no overflow
          doc_.fail(e, "<p> has " + std::to_string(n) + " indices, count=\"" + std::to_string(count) +
                           "\" triangles need " + std::to_string(count * 3 * stride));
        sizes.assign(count, 3);
      } else {
        if (count > 0) sizes = doc_.integers(doc_.child(e, "vcount"));
        if (sizes.size() != count)
          doc_.fail(e, "<vcount> has " + std::to_string(sizes.size()) + " entries, count=\"" + std::to_string(count) +
                           "\" needs one per polygon");
        uint64_t corners = 0;  // fewer than 2^32 sizes below 2^32 each: no overflow
        for (uint32_t s : sizes) corners += s;
        // stride <= 64: the product overflows only past 2^58 corners.
        const bool huge = corners > (uint64_t(1) << 58);
        if (huge || corners * stride != n)
          doc_.fail(e, "<p> has " + std::to_string(n) + " indices, vcount needs " +
                           (huge ? "more than 2^64" : std::to_string(corners * stride)));
      }
      out.start.reserve(sizes.size() + 1);
      for (uint32_t s : sizes) out.start.push_back(out.start.back() + s * stride);
      return out;
    }
    // <polygons>, <trifans>, <tristrips>: one <p> per polygon (or <ph>, a
    // polygon with holes, in <polygons>).
    size_t holes = 0;
    for (XmlNode c : e.children()) {
      if (c.type() != pugi::node_element) continue;
      XmlNode p = c;
      if (name == "polygons" && std::strcmp(c.name(), "ph") == 0) {
        p = doc_.child(c, "p");
        for (XmlNode h : c.children("h")) (void)h, ++holes;
      } else if (std::strcmp(c.name(), "p") != 0) {
        continue;
      }
      std::vector<uint32_t> indices = doc_.integers(p);
      if (indices.size() % stride != 0)
        doc_.fail(p, "has " + std::to_string(indices.size()) + " indices, not a multiple of the " +
                         std::to_string(stride) + " per corner that the inputs' offsets ask for");
      out.add(indices);
    }
    if (out.size() != count)
      doc_.fail(e, "count=\"" + std::to_string(count) + "\" but it has " + std::to_string(out.size()) + " <p>" +
                       (name == "polygons" ? " and <ph>" : "") + " elements");
    if (holes > 0) doc_.warn(e, std::to_string(holes) + " hole(s) (<h> in <ph>) ignored: the outer polygons are filled");
    return out;
  }
};

}  // namespace

std::vector<ColladaMeshPart> read_collada_mesh(ColladaDocument& doc, XmlNode mesh) {
  return MeshReader(doc, mesh).read();
}

}  // namespace pt
