#pragma once
// A scene across the boundary (README.md beside this file). Parts 3 and 4
// hand the task functions a tracer over a whole scene and a hit in it: the
// verifier sends the scene once, the worker rebuilds it (and its BVH, with the
// solution's Part 2) and keeps it under the id the verifier gave, and each
// call then names it (SceneTracer). A hit record's primitive and BSDF cross as
// their index in the scene, so that they mean the same object on both sides.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "geometry/intersection.h"
#include "hit_codec.h"
#include "objects.h"
#include "render/pathtracer.h"
#include "scene/path_guard.h"
#include "scene/scene.h"
#include "wire.h"

namespace pt::boundary {

// The verifier's side: the scene's objects by address.
struct SceneIndex {
  std::unordered_map<const Primitive*, int64_t> primitives;
  std::unordered_map<const BSDF*, int64_t> bsdfs;
};

// Writes the scene's BSDFs, its primitives in order, its lights and camera,
// and fills `index`. Only the framework's own types cross (scene/bsdf.h,
// scene/path_guard.h, scene/light.h, triangles and spheres): a subclass of
// a test's would lose what it adds, and is a std::logic_error that names it.
void put_scene(Writer& w, const Scene& scene, SceneIndex& index);
// The worker's side: the scene rebuilt, its BVH built.
std::unique_ptr<Scene> get_scene(Reader& r);

void put_scene_hit(Writer& w, const Intersection& hit, const SceneIndex& index);
void get_scene_hit(Reader& r, Intersection& hit, const Scene& scene);

// The verifier's side (verifier_link.cpp): the id under which the worker
// keeps `scene`, sent now unless it is the scene sent last (the same object,
// unchanged since: Scene::revision), and the index of its objects. Call with
// the link held until the calls that name it are made.
struct SceneRef {
  uint64_t id;
  const SceneIndex& index;
};
SceneRef refer_to(const Scene& scene);

// The worker's side: keeps the scene the verifier defines, and finds it by
// the id a call names.
void serve_scene_definitions(Link& link);
const Scene& scene_named(uint64_t id);

// A tracer over its scene (tasks.def's SceneTracer): the scene's id, the
// settings, and the path guard's state (scene/path_guard.h). The guard
// crosses as its count and limit with each call and comes back with the
// answer: the worker's guard stops a path there, and the test's own then
// throws its own message at the call that was stopped, as in one process.
// The guard's word can fail a test, never pass one.
struct SceneTracer {
  static constexpr bool kCallsBack = false;
  struct Sent : SentObject {
    explicit Sent(const PathTracer& t) : self(t), scene(refer_to(*t.scene)) {}
    void put(Writer& w) const {
      const PathGuard& guard = path_guard();
      w.put(scene.id).put(self.settings).put(guard.samples).put(guard.limit);
    }
    void put_hit(Writer& w, const Intersection& h) const { put_scene_hit(w, h, scene.index); }
    void take_after(Reader& r) {
      r.get(samples);
      stopped = r.get<uint8_t>() != 0;
    }
    void after_call() {
      PathGuard& guard = path_guard();
      guard.samples = samples;
      if (stopped) {
        guard.samples = std::max(guard.samples, guard.limit);
        guard.count();  // throws, saying what it says in one process
      }
    }
    const PathTracer& self;
    SceneRef scene;
    int64_t samples = 0;
    bool stopped = false;
  };
  struct Held {
    explicit Held(Reader& in) : scene(scene_named(in.get<uint64_t>())), tracer(scene, in.get<RenderSettings>()) {
      in.get(samples, limit);
    }
    void get_hit(Reader& r, Intersection& h) const { get_scene_hit(r, h, scene); }
    // The call under the guard, from where the verifier's was: a path it
    // stops is an answer that says so (a run goes on).
    template <class Fn, class... Args>
    Spectrum invoke(Fn fn, Args&&... args) {
      PathGuard& guard = path_guard();
      guard.samples = samples;
      guard.limit = limit;
      stopped = false;
      try {
        return (tracer.*fn)(std::forward<Args>(args)...);
      } catch (const PathGuard::Stopped&) {
        stopped = true;
        return Spectrum(0.0);
      }
    }
    void put_after(Writer& w) const { w.put(path_guard().samples).put(static_cast<uint8_t>(stopped)); }

    const Scene& scene;
    const PathTracer tracer;
    int64_t samples = 0, limit = 0;
    bool stopped = false;
  };
};

}  // namespace pt::boundary
