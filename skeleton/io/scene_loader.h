#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace pt {

// A scene file that cannot be used. what() names the file and the place:
// "scenes/x.json:12:5: ..." for syntax, "scenes/x.json: /shapes/2/radius: ..."
// for content.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LoadedScene {
  Scene scene;
  // What the file asked for that the framework approximates or ignores; the
  // command line prints these, tests can assert on them.
  std::vector<std::string> warnings;
};

// Whether load_scene builds the BVH (a summary of the scene needs none, and so
// works before Part 2 is done).
enum class BuildBvh { No, Yes };

// Loads a scene file, by extension: .json (the framework's format) or .dae
// (COLLADA, io/collada_loader.h). Throws SceneError.
LoadedScene load_scene(const std::string& path, BuildBvh bvh = BuildBvh::Yes);

// Loads a camera file (a JSON object with the scene format's "camera" fields).
Camera load_camera(const std::string& path);

}  // namespace pt
