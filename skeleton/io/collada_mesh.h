#pragma once
// The <mesh> of a COLLADA <geometry>, read into indexed triangles in the
// geometry's own frame (the scene graph places them). Internal to the loader.
#include <array>
#include <string>
#include <vector>

#include "io/collada_document.h"

namespace pt {

// The faces of one primitive element (<triangles>, <polylist>, <polygons>,
// <trifans> or <tristrips>): they share one material symbol.
struct ColladaMeshPart {
  XmlNode element;       // for messages
  std::string material;  // the element's material symbol ("" when it names none)
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // one per position, or empty: the scene computes them
  std::vector<std::array<uint32_t, 3>> faces;
};

// Reads every primitive element of `mesh`: VERTEX (through <vertices>, which
// may also carry NORMAL), NORMAL and TEXCOORD inputs at their offsets, polygons
// triangulated. A mesh vertex is made per distinct (position, normal) pair.
// Fails naming the element on broken data (counts that disagree, indices out
// of range, missing sources); warns about what it skips (lines, polygons with
// fewer than 3 corners, holes) or approximates.
std::vector<ColladaMeshPart> read_collada_mesh(ColladaDocument& doc, XmlNode mesh);

}  // namespace pt
