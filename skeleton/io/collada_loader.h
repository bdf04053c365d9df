#pragma once
// COLLADA 1.4 (.dae) scenes in the course's dialect: Blender's exporter plus
// <extra><technique profile="CGL"> spheres, lights and materials.
// scenes/README.md ("COLLADA scenes") says what is read, how the axes are
// converted and what is approximated.
#include <cstddef>
#include <string>

#include "io/scene_loader.h"

namespace pt {

// Bounds on what a file may ask for, so that no file, however small, runs the
// loader out of memory or time (<instance_node> can repeat a subtree
// exponentially often) or out of stack (the scene graph is walked recursively).
struct ColladaLimits {
  size_t max_node_depth = 128;             // nested <node>s and <instance_node>s
  size_t max_node_instances = 1'000'000;   // nodes visited, every instantiation counted
  size_t max_triangles = 20'000'000;       // after instancing (about 3 GB of scene)
  size_t max_warnings = 100;               // kept; the rest are counted in one line
};

// Reads `path` into out->scene (everything but the BVH, which load_scene
// builds) and out->warnings. Throws SceneError naming the file and the place:
// "file.dae:LINE:COL: ..." for XML syntax, "file.dae: /COLLADA/...: ..." (an
// element path) for content.
void load_collada(const std::string& path, LoadedScene* out, const ColladaLimits& limits = {});

}  // namespace pt
