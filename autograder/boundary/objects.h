#pragma once
// How the object a task function is called on crosses (tasks.def's object
// column). Each codec has two halves:
//   Sent  the verifier's, made from the test's object for one call: puts
//         what the worker needs, and says what the answer's hit records and
//         nodes name; it may hold a scope for the call's callbacks
//   Held  the worker's, rebuilt from what crossed: the object the student's
//         function is called on
// Scenes and BVHs are in scene_codec.h and bvh_codec.h.
#include <memory>
#include <utility>

#include "core/vec.h"
#include "crossing.h"
#include "geometry/mesh.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "hit_codec.h"
#include "render/pathtracer.h"
#include "scene/bsdf.h"
#include "scene/camera.h"
#include "verifier_link.h"
#include "worker_link.h"

namespace pt::boundary {

// What every Sent does unless it says otherwise: nothing comes back after
// the answer's own values.
struct SentObject {
  void take_after(Reader&) {}
  void after_call() {}
};

// What every Held does unless it says otherwise: calls the function on its
// object.
template <class Derived>
struct HeldObject {
  template <class Fn, class... Args>
  decltype(auto) invoke(Fn fn, Args&&... args) {
    return (static_cast<Derived&>(*this).object().*fn)(std::forward<Args>(args)...);
  }
  void put_after(Writer&) const {}
};

// A free function's: no object.
struct NoObject {
  static constexpr bool kCallsBack = false;
  struct Sent : SentObject {
    void put(Writer&) const {}
  };
  struct Held {
    explicit Held(Reader&) {}
    template <class Fn, class... Args>
    decltype(auto) invoke(Fn fn, Args&&... args) {
      return fn(std::forward<Args>(args)...);
    }
    void put_after(Writer&) const {}
  };
};

// A plain object, as its bytes (a camera, a box).
template <class T>
struct Bytes {
  static constexpr bool kCallsBack = false;
  struct Sent : SentObject {
    explicit Sent(const T& self) : self(self) {}
    void put(Writer& w) const { w.put(self); }
    const T& self;
  };
  struct Held : HeldObject<Held> {
    explicit Held(Reader& in) : value(in.get<T>()) {}
    const T& object() const { return value; }
    T value;
  };
};

// The BSDF of a shape that has one on the verifier's side: a hit's BSDF only
// needs to be told apart from "none" and "something else".
inline const BSDF* stand_in_bsdf() {
  static const DiffuseBSDF b{Spectrum(0.5)};
  return &b;
}

// A triangle: its positions, normals and whether it has a BSDF.
struct TriangleShape {
  static constexpr bool kCallsBack = false;
  struct Sent : SentObject, AskedHits {
    explicit Sent(const Triangle& t) : AskedHits(&t), self(t) {}
    void put(Writer& w) const {
      w.put(self.p1()).put(self.p2()).put(self.p3()).put(self.n1()).put(self.n2()).put(self.n3());
      w.put(static_cast<uint8_t>(self.get_bsdf() != nullptr));
    }
    const Triangle& self;
  };
  // The shape, rebuilt before the hits that name it.
  struct Rebuilt {
    explicit Rebuilt(Reader& in) {
      mesh.positions.resize(3);
      mesh.normals.resize(3);
      for (Vec3& p : mesh.positions) in.get(p);
      for (Vec3& n : mesh.normals) in.get(n);
      mesh.faces.push_back({0u, 1u, 2u});
      mesh.bsdf = in.get<uint8_t>() ? stand_in_bsdf() : nullptr;
    }
    Mesh mesh;
    Triangle triangle{&mesh, 0, 1, 2};
  };
  struct Held : HeldObject<Held>, Rebuilt, AskedHits {
    explicit Held(Reader& in) : Rebuilt(in), AskedHits(&triangle) {}
    Held(const Held&) = delete;
    const Triangle& object() const { return triangle; }
  };
};

// A sphere: its centre, radius, r² and whether it has a BSDF.
struct SphereShape {
  static constexpr bool kCallsBack = false;
  struct Sent : SentObject, AskedHits {
    explicit Sent(const Sphere& s) : AskedHits(&s), self(s) {}
    void put(Writer& w) const {
      w.put(self.o).put(self.r).put(self.r2).put(static_cast<uint8_t>(self.get_bsdf() != nullptr));
    }
    const Sphere& self;
  };
  struct Rebuilt {
    explicit Rebuilt(Reader& in) : sphere(read(in)) {}
    static Sphere read(Reader& in) {
      const auto o = in.get<Vec3>();
      const auto r = in.get<double>(), r2 = in.get<double>();
      Sphere s(o, r, in.get<uint8_t>() ? stand_in_bsdf() : nullptr);
      s.r2 = r2;
      return s;
    }
    Sphere sphere;
  };
  struct Held : HeldObject<Held>, Rebuilt, AskedHits {
    explicit Held(Reader& in) : Rebuilt(in), AskedHits(&sphere) {}
    Held(const Held&) = delete;
    const Sphere& object() const { return sphere; }
  };
};

// The diffuse BSDF: its albedo and emission.
struct Diffuse {
  static constexpr bool kCallsBack = false;
  struct Sent : SentObject {
    explicit Sent(const DiffuseBSDF& b) : self(b) {}
    void put(Writer& w) const { w.put(self.reflectance).put(self.emission); }
    const DiffuseBSDF& self;
  };
  struct Held : HeldObject<Held> {
    explicit Held(Reader& in) : bsdf(in.get<Spectrum>()) { in.get(bsdf.emission); }
    const DiffuseBSDF& object() const { return bsdf; }
    DiffuseBSDF bsdf;
  };
};

// The worker's stand-in for the verifier's PathTracer: the student's pixel
// loop calls est_radiance_global_illumination, and the verifier's own tracer
// answers, be it a test's script (which counts each sample) or the solution.
class RemoteTracer : public PathTracer {
 public:
  RemoteTracer(const Scene& scene, const RenderSettings& settings) : PathTracer(scene, settings) {}
  Spectrum est_radiance_global_illumination(const Ray& r, Rng& rng) const override {
    Writer args;
    Crossing<Ray>::put(args, r);
    args.put(rng);
    const std::string answer = worker_link().call(Call::EstRadiance, args);
    Reader result(answer);
    const auto radiance = result.get<Spectrum>();
    result.get(rng);
    result.finish();
    return radiance;
  }
};

// A tracer whose pixel is sampled: its settings and camera cross; each
// sample's radiance is a call back (EstRadiance) to the tracer the test made.
struct PixelTracer {
  static constexpr bool kCallsBack = true;
  struct Sent : SentObject {
    explicit Sent(const PathTracer& t) : scope(g_tracer, &t), self(t) {}
    void put(Writer& w) const { w.put(self.settings).put(*self.camera); }
    Scoped<const PathTracer*> scope;
    const PathTracer& self;
  };
  struct Held : HeldObject<Held> {
    explicit Held(Reader& in) : settings(in.get<RenderSettings>()), tracer(read_camera(in), settings) {}
    const PathTracer& object() const { return tracer; }

   private:
    const Scene& read_camera(Reader& in) {
      in.get(scene.camera);
      return scene;
    }
    RenderSettings settings;
    Scene scene;
    RemoteTracer tracer;
  };
};

}  // namespace pt::boundary
