#include "scene_codec.h"

#include <stdexcept>
#include <string>
#include <typeinfo>

#include "geometry/counted.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "hit_codec.h"
#include "scene/path_guard.h"

namespace pt::boundary {
namespace {

enum class BsdfKind : uint8_t { Diffuse = 1, Emission = 2, GuardedDiffuse = 3, NormalMirror = 4 };
enum class PrimitiveKind : uint8_t { Triangle = 1, Sphere = 2 };
enum class LightKind : uint8_t { Point = 1, Directional = 2, Area = 3, Sky = 4 };

// Only the framework's own types cross: a subclass (a test's instrumented
// BSDF) would lose what it adds.
template <class T, class Base>
const T* exactly(const Base& object) {
  return typeid(object) == typeid(T) ? static_cast<const T*>(&object) : nullptr;
}

[[noreturn]] void cannot_cross(const char* what, const std::type_info& type) {
  throw std::logic_error(std::string("the process boundary cannot carry this ") + what + " (" + type.name() +
                         ") to the worker: only the framework's own types cross (autograder/boundary/README.md)");
}

const BSDF* bsdf_at(int64_t i, const Scene& scene) {
  return object_at(i, scene.bsdfs.size(), [&](size_t k) { return scene.bsdfs[k].get(); }, elsewhere_bsdf());
}

void put_bsdf(Writer& w, const BSDF& b) {
  if (const auto* d = exactly<DiffuseBSDF>(b)) {
    w.put(BsdfKind::Diffuse).put(d->reflectance).put(d->emission);
  } else if (const auto* e = exactly<EmissionBSDF>(b)) {
    w.put(BsdfKind::Emission).put(e->radiance);
  } else if (const auto* g = exactly<GuardedDiffuse>(b)) {
    w.put(BsdfKind::GuardedDiffuse).put(g->albedo()).put(g->emission());
  } else if (exactly<NormalMirror>(b)) {
    w.put(BsdfKind::NormalMirror);
  } else {
    cannot_cross("BSDF", typeid(b));
  }
}

void put_light(Writer& w, const Light& l) {
  if (const auto* p = exactly<PointLight>(l)) {
    w.put(LightKind::Point).put(p->intensity).put(p->position);
  } else if (const auto* d = exactly<DirectionalLight>(l)) {
    w.put(LightKind::Directional).put(d->radiance).put(d->direction);
  } else if (const auto* a = exactly<AreaLight>(l)) {
    w.put(LightKind::Area).put(a->radiance).put(a->position).put(a->direction).put(a->dim_x).put(a->dim_y);
  } else if (const auto* s = exactly<SkyLight>(l)) {
    w.put(LightKind::Sky).put(s->radiance);
  } else {
    cannot_cross("light", typeid(l));
  }
}

// Rebuilt with the fields as they were sent: the constructors normalise the
// direction, which could move a unit vector by a rounding step.
void get_light(Reader& r, Scene& scene) {
  switch (r.get<LightKind>()) {
    case LightKind::Point: {
      const auto intensity = r.get<Spectrum>();
      scene.lights.push_back(std::make_unique<PointLight>(intensity, r.get<Vec3>()));
      return;
    }
    case LightKind::Directional: {
      const auto radiance = r.get<Spectrum>();
      auto light = std::make_unique<DirectionalLight>(radiance, Vec3(0, 0, 1));
      r.get(light->direction);
      scene.lights.push_back(std::move(light));
      return;
    }
    case LightKind::Area: {
      const auto radiance = r.get<Spectrum>();
      const auto position = r.get<Vec3>(), direction = r.get<Vec3>(), dim_x = r.get<Vec3>(), dim_y = r.get<Vec3>();
      auto light = std::make_unique<AreaLight>(radiance, position, direction, dim_x, dim_y);
      light->direction = direction;
      scene.lights.push_back(std::move(light));
      return;
    }
    case LightKind::Sky:
      scene.add_light<SkyLight>(r.get<Spectrum>());
      return;
  }
  throw std::runtime_error("a light of unknown kind");
}

}  // namespace

void put_scene(Writer& w, const Scene& scene, SceneIndex& index) {
  index = SceneIndex();
  w.put(static_cast<uint64_t>(scene.bsdfs.size()));
  for (size_t i = 0; i < scene.bsdfs.size(); ++i) {
    put_bsdf(w, *scene.bsdfs[i]);
    index.bsdfs[scene.bsdfs[i].get()] = static_cast<int64_t>(i);
  }
  w.put(static_cast<uint64_t>(scene.primitives.size()));
  for (size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = *scene.primitives[i];
    index.primitives[&p] = static_cast<int64_t>(i);
    if (const auto* t = dynamic_cast<const Triangle*>(&p)) {
      w.put(PrimitiveKind::Triangle).put(t->p1()).put(t->p2()).put(t->p3()).put(t->n1()).put(t->n2()).put(t->n3());
    } else if (const auto* s = dynamic_cast<const Sphere*>(&p)) {
      w.put(PrimitiveKind::Sphere).put(s->o).put(s->r).put(s->r2);
    } else {
      cannot_cross("primitive", typeid(p));
    }
    w.put(index_of(p.get_bsdf(), index.bsdfs));
  }
  w.put(static_cast<uint64_t>(scene.lights.size()));
  for (const auto& l : scene.lights) put_light(w, *l);
  w.put(scene.camera);
}

std::unique_ptr<Scene> get_scene(Reader& r) {
  auto scene = std::make_unique<Scene>();
  const uint64_t bsdfs = r.get<uint64_t>();
  for (uint64_t i = 0; i < bsdfs; ++i) {
    switch (r.get<BsdfKind>()) {
      case BsdfKind::Diffuse: {
        const auto reflectance = r.get<Spectrum>();
        scene->add_bsdf<DiffuseBSDF>(reflectance, r.get<Spectrum>());
        break;
      }
      case BsdfKind::Emission: scene->add_bsdf<EmissionBSDF>(r.get<Spectrum>()); break;
      case BsdfKind::GuardedDiffuse: {
        const auto reflectance = r.get<Spectrum>();
        scene->add_bsdf<GuardedDiffuse>(reflectance, r.get<Spectrum>());
        break;
      }
      case BsdfKind::NormalMirror: scene->add_bsdf<NormalMirror>(); break;
      default: throw std::runtime_error("a BSDF of unknown kind");
    }
  }
  // Each BSDF's triangles go into one mesh of their own, three vertices each,
  // in the order of the verifier's primitives (a hit names its index).
  std::unordered_map<int64_t, Mesh*> mesh_of;
  const uint64_t primitives = r.get<uint64_t>();
  for (uint64_t i = 0; i < primitives; ++i) {
    const auto kind = r.get<PrimitiveKind>();
    if (kind == PrimitiveKind::Triangle) {
      Vec3 v[6];
      for (Vec3& x : v) r.get(x);
      const int64_t b = r.get<int64_t>();
      Mesh*& mesh = mesh_of[b];
      if (!mesh) {
        scene->meshes.push_back(std::make_unique<Mesh>());
        mesh = scene->meshes.back().get();
        mesh->bsdf = bsdf_at(b, *scene);
      }
      const auto first = static_cast<uint32_t>(mesh->positions.size());
      mesh->positions.insert(mesh->positions.end(), {v[0], v[1], v[2]});
      mesh->normals.insert(mesh->normals.end(), {v[3], v[4], v[5]});
      mesh->faces.push_back({first, first + 1, first + 2});
      scene->primitives.push_back(std::make_unique<Counted<Triangle>>(mesh, first, first + 1, first + 2));
    } else if (kind == PrimitiveKind::Sphere) {
      const auto o = r.get<Vec3>();
      const auto radius = r.get<double>(), r2 = r.get<double>();
      auto sphere = std::make_unique<Counted<Sphere>>(o, radius, bsdf_at(r.get<int64_t>(), *scene));
      sphere->r2 = r2;
      scene->primitives.push_back(std::move(sphere));
    } else {
      throw std::runtime_error("a primitive of unknown kind");
    }
  }
  const uint64_t lights = r.get<uint64_t>();
  for (uint64_t i = 0; i < lights; ++i) get_light(r, *scene);
  r.get(scene->camera);
  scene->build();
  return scene;
}

void put_scene_hit(Writer& w, const Intersection& hit, const SceneIndex& index) {
  w.put(hit.t).put(hit.n).put(hit.barycentric).put(index_of(hit.primitive, index.primitives));
  w.put(index_of(hit.bsdf, index.bsdfs));
}

void get_scene_hit(Reader& r, Intersection& hit, const Scene& scene) {
  r.get(hit.t, hit.n, hit.barycentric);
  hit.primitive = object_at(r.get<int64_t>(), scene.primitives.size(),
                            [&](size_t k) { return scene.primitives[k].get(); }, elsewhere_primitive());
  hit.bsdf = bsdf_at(r.get<int64_t>(), scene);
}

namespace {

struct SentScene {
  uint64_t id = 0;
  std::unique_ptr<Scene> scene;
};

SentScene& sent_scene() {
  static SentScene s;
  return s;
}

}  // namespace

void serve_scene_definitions(Link& link) {
  link.on(Call::DefineScene, [](Reader& in, Writer&) {
    const auto id = in.get<uint64_t>();
    sent_scene().scene.reset();
    sent_scene().scene = get_scene(in);
    sent_scene().id = id;
  });
}

const Scene& scene_named(uint64_t id) {
  if (!sent_scene().scene || id != sent_scene().id) throw std::runtime_error("a call names a scene the worker was not sent");
  return *sent_scene().scene;
}

}  // namespace pt::boundary
