#pragma once
// Reading an input file (scene, mesh, camera) whole, within a size bound
// checked before anything is read, so that a multi-gigabyte file given by
// mistake (or on purpose) is refused at once instead of filling the memory.
#include <cstdint>
#include <string>

namespace pt {

// Bounds on what the loaders read. Checked against the file's size before
// reading, and again while reading (a file may grow, and /proc files report 0).
// A JSON scene or camera holds no geometry (meshes are separate files): the
// largest shipped scene is 2 KiB, and 16 MiB is some 100,000 spheres.
constexpr uint64_t kMaxSceneFileBytes = uint64_t(16) << 20;
// Meshes (OBJ; COLLADA scenes carry theirs inline): loading takes about 6
// times the file in memory (453 MB for a 74 MB OBJ of 2 million triangles,
// tests/cli/README.md), so 512 MiB (some 14 million triangles, far beyond the
// course's meshes) is about 3 GB.
constexpr uint64_t kMaxMeshFileBytes = uint64_t(512) << 20;

// "16 MiB", "2 GiB", "532 bytes": a size as a message shows it.
std::string format_bytes(uint64_t bytes);

// Throws SceneError "path: ..." unless `path` names a regular file (following
// symbolic links): missing, a directory, a device, a symlink loop. `what`
// names the kind of file, with its article ("a scene file", "an EXR image").
void check_input_path(const std::string& path, const char* what);

// The whole of `path`. Throws SceneError "path: ..." as check_input_path
// does, when the file cannot be read, and when it is larger than max_bytes
// (the message gives both sizes).
std::string read_input_file(const std::string& path, uint64_t max_bytes, const char* what);

}  // namespace pt
