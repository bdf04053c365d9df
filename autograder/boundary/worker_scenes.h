#pragma once
// The worker's copy of the scene the verifier sent last (scene_codec.h), for
// the parts whose calls name a scene.
#include <memory>
#include <stdexcept>

#include "scene_codec.h"

namespace pt::boundary {

struct SentScene {
  uint64_t id = 0;
  std::unique_ptr<Scene> scene;
};

inline SentScene& sent_scene() {
  static SentScene s;
  return s;
}

inline void serve_scene_definitions(Link& link) {
  link.on(Call::DefineScene, [](Reader& in, Writer&) {
    const auto id = in.get<uint64_t>();
    sent_scene().scene.reset();
    sent_scene().scene = get_scene(in);
    sent_scene().id = id;
  });
}

// The scene a call names (its first value).
inline const Scene& scene_named(Reader& in) {
  const auto id = in.get<uint64_t>();
  if (!sent_scene().scene || id != sent_scene().id)
    throw std::runtime_error("a call names a scene the worker was not sent");
  return *sent_scene().scene;
}

}  // namespace pt::boundary
