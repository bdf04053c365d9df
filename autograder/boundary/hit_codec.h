#pragma once
// A hit record on a call to one primitive (Part 1's shapes). Its pointers
// mean nothing in the other process, so each crosses as what it points at:
// nothing, the primitive asked (or its BSDF), or something else, which the
// receiving side maps to an object of its own. The calls on a scene and on a
// BVH name their objects by index instead (below).
#include <cstdint>
#include <unordered_map>

#include "geometry/intersection.h"
#include "geometry/primitive.h"
#include "geometry/sphere.h"
#include "scene/bsdf.h"
#include "wire.h"

namespace pt::boundary {

// What a hit's "something else" becomes on a side that has no such object
// of its own: objects nobody else made, so that no test's object equals them.
inline const Primitive* elsewhere_primitive() {
  static const Sphere s(Vec3(0.0), 0.0, nullptr);
  return &s;
}
inline const BSDF* elsewhere_bsdf() {
  static const DiffuseBSDF b{Spectrum(0.0)};
  return &b;
}

// The calls on a scene and on a BVH name an object by its index in what was
// sent, or as one of these.
constexpr int64_t kNoObject = -1;         // a null pointer
constexpr int64_t kElsewhereObject = -2;  // an object that is not one of those sent

template <class T>
int64_t index_of(const T* object, const std::unordered_map<const T*, int64_t>& index) {
  if (!object) return kNoObject;
  const auto found = index.find(object);
  return found == index.end() ? kElsewhereObject : found->second;
}

// The object index `i` names among `count` sent (`at(i)` gives one): a wrong
// index is what no honest peer sends.
template <class T, class At>
const T* object_at(int64_t i, size_t count, At&& at, const T* elsewhere) {
  if (i == kNoObject) return nullptr;
  if (i == kElsewhereObject) return elsewhere;
  if (i < 0 || static_cast<uint64_t>(i) >= count) throw LinkBroken("an object index out of range");
  return at(static_cast<size_t>(i));
}

// The hits of calls on `asked`. Each side uses it the same way: a hit sent
// remembers what it pointed at, and "something else" in the hit that comes
// back is that again when it was something else too (the verifier's own
// object), otherwise a stand-in.
class AskedHits {
 public:
  explicit AskedHits(const Primitive* asked) : asked_(asked), asked_bsdf_(asked->get_bsdf()) {}

  void put_hit(Writer& w, const Intersection& h) {
    before_primitive_ = h.primitive;
    before_bsdf_ = h.bsdf;
    w.put(h.t).put(h.n).put(h.barycentric).put(token(h.primitive, asked_)).put(token(h.bsdf, asked_bsdf_));
  }

  void get_hit(Reader& r, Intersection& h) const {
    r.get(h.t, h.n, h.barycentric);
    const auto primitive = r.get<Points>(), bsdf = r.get<Points>();
    h.primitive = named(primitive, asked_, before_primitive_, elsewhere_primitive());
    h.bsdf = named(bsdf, asked_bsdf_, before_bsdf_, elsewhere_bsdf());
  }

 private:
  enum class Points : uint8_t { Nothing = 0, Asked = 1, Elsewhere = 2 };
  static Points token(const void* p, const void* asked) {
    return p == nullptr ? Points::Nothing : p == asked ? Points::Asked : Points::Elsewhere;
  }
  template <class T>
  static const T* named(Points p, const T* asked, const T* before, const T* stand_in) {
    if (p == Points::Nothing) return nullptr;
    if (p == Points::Asked) return asked;
    return before && before != asked ? before : stand_in;
  }

  const Primitive* asked_;
  const BSDF* asked_bsdf_;
  const Primitive* before_primitive_ = nullptr;
  const BSDF* before_bsdf_ = nullptr;
};

}  // namespace pt::boundary
