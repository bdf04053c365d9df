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

// Loads a scene file (format by extension: .json) and builds its BVH.
// Throws SceneError.
LoadedScene load_scene(const std::string& path);

// Loads a camera file (a JSON object with the scene format's "camera" fields).
Camera load_camera(const std::string& path);

}  // namespace pt
