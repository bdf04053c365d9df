#pragma once
// Checks an OBJ file's text before tinyobjloader parses it. tinyobjloader
// reads what it can and quietly makes up the rest: `v nan 1 0`, `v 1x 2 3`
// and `v 1 2` load with zeros in place of what it could not read, an index
// too large for an int wraps around, and a face of 200,000 vertices takes
// minutes to triangulate. Internal to the OBJ loader.
#include <string>

namespace pt {

// Corners a face may have. Triangulating an n-gon costs about n^2 (measured:
// 16,000 corners 0.53 s, 1,024 corners 2 ms), so with this bound no file
// within kMaxMeshFileBytes takes much longer to triangulate than to read.
constexpr int kMaxFaceVertices = 1024;

// Throws SceneError "path:LINE: ..." at the first line that tinyobjloader
// would misread: a NUL byte; a `v` or `vn` without three numbers, or with a
// value that is not a decimal number of magnitude at most 1e30 (the scene
// format's bound) with an exponent within +-300; a face, line or point
// corner that is not `v`, `v/vt`, `v//vn` or `v/vt/vn` with int indices, an
// index of 0 or beyond the elements the file has; a face of more than
// kMaxFaceVertices corners.
void check_obj_text(const std::string& text, const std::string& path);

}  // namespace pt
