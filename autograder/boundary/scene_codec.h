#pragma once
// A scene across the boundary (README.md beside this file). Parts 3 and 4
// hand the task functions a tracer over a whole scene and a hit in it: the
// verifier sends the scene once, the worker rebuilds it (and its BVH, with the
// solution's Part 2) and keeps it under the id the verifier gave, and each
// call then names it. A hit record's primitive and BSDF cross as their index
// in the scene, so that they mean the same object on both sides.
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "geometry/intersection.h"
#include "scene/scene.h"
#include "wire.h"

namespace pt::boundary {

// Indices of a hit record that name no object of the scene.
constexpr int64_t kNoObject = -1;         // a null pointer
constexpr int64_t kElsewhereObject = -2;  // an object that is not the scene's

// The verifier's side: the scene's objects by address.
struct SceneIndex {
  std::unordered_map<const Primitive*, int64_t> primitives;
  std::unordered_map<const BSDF*, int64_t> bsdfs;
};

enum class BsdfKind : uint8_t { Diffuse = 1, Emission = 2, GuardedDiffuse = 3, NormalMirror = 4 };

// BSDF types of the tests that the worker has copies of (path_guard_copy.h):
// the verifier's proxies set an encoder that writes their kind and values and
// returns true, or returns false for a type it does not know.
using BsdfEncoder = bool (*)(Writer& w, const BSDF& bsdf);
void set_bsdf_encoder(BsdfEncoder encode);

// Writes the scene's BSDFs, its primitives in order, its lights and camera,
// and fills `index`. What cannot cross (a BSDF, light or primitive of a type
// the framework does not define) is a std::logic_error that names it.
void put_scene(Writer& w, const Scene& scene, SceneIndex& index);
// The worker's side: the scene rebuilt, its BVH built.
std::unique_ptr<Scene> get_scene(Reader& r);

// What a BSDF's sample_f gives: its value, the direction and its pdf.
struct BsdfSample {
  Spectrum f;
  Vec3 wi;
  double pdf;
};

void put_scene_hit(Writer& w, const Intersection& hit, const SceneIndex& index);
void get_scene_hit(Reader& r, Intersection& hit, const Scene& scene);

}  // namespace pt::boundary
