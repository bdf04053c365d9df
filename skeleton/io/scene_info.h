#pragma once
// What `pathtracer --scene-info` prints: a summary of a loaded scene as one
// JSON object, for scripts and tests.
#include <string>

#include "io/scene_loader.h"

namespace pt {

// {"triangles": N, "spheres": N, "meshes": N,
//  "lights": {"area": N, "point": N, "directional": N, "sky": N},
//  "emissive_shapes": N,
//  "camera": {"position": [x, y, z], "direction": [x, y, z], "hfov": deg, "vfov": deg},
//  "bounds": {"min": [x, y, z], "max": [x, y, z]}, "warnings": ["...", ...]}
// The camera is scene.camera as it stands (the command line first applies -c,
// --course-camera and the image's aspect); bounds are null for an empty scene.
// emissive_shapes counts meshes and spheres whose material emits.
std::string scene_info_json(const LoadedScene& loaded);

}  // namespace pt
