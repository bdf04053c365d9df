#pragma once
// How values cross the boundary (tasks.def's arguments and answers): one
// codec per type, and the roles an argument can have.
//
// A plain value crosses as its bytes (both ends are the same build); a value
// that a replay compares crosses field by field, so that no padding (whatever
// the other side left there) makes two equal answers differ. A hit record and
// a BVH node name objects, whose addresses mean nothing in the other process:
// they cross as the object the call is on says (objects.h).
#include <cstdint>
#include <functional>
#include <type_traits>
#include <vector>

#include "core/ray.h"
#include "core/rng.h"
#include "geometry/bvh.h"
#include "render/pathtracer.h"
#include "wire.h"

namespace pt::boundary {

template <class T>
struct Crossing {
  static_assert(std::is_trivially_copyable_v<T>, "a value without a codec of its own crosses as its bytes");
  static void put(Writer& w, const T& v) { w.put(v); }
  static T get(Reader& r) { return r.get<T>(); }
};

template <>
struct Crossing<bool> {
  static void put(Writer& w, bool v) { w.put(static_cast<uint8_t>(v)); }
  static bool get(Reader& r) { return r.get<uint8_t>() != 0; }
};

template <>
struct Crossing<Ray> {
  static void put(Writer& w, const Ray& r) { w.put(r.o).put(r.d).put(r.min_t).put(r.max_t).put(r.depth); }
  static Ray get(Reader& r) {
    Ray ray;
    r.get(ray.o, ray.d, ray.min_t, ray.max_t, ray.depth);
    return ray;
  }
  // What a query changes of a const Ray: its range (mutable), which a hit shrinks.
  static void put_range(Writer& w, const Ray& r) { w.put(r.min_t).put(r.max_t); }
  static void get_range(Reader& r, const Ray& ray) { r.get(ray.min_t, ray.max_t); }
};

template <>
struct Crossing<PixelEstimate> {
  static void put(Writer& w, const PixelEstimate& e) { w.put(e.radiance).put(e.num_samples); }
  static PixelEstimate get(Reader& r) {
    PixelEstimate e;
    r.get(e.radiance, e.num_samples);
    return e;
  }
};

// Any length the message can hold: a wrong one is for the tests to see.
template <class T>
struct Crossing<std::vector<T>> {
  static void put(Writer& w, const std::vector<T>& v) { w.put_vector(v); }
  static std::vector<T> get(Reader& r) { return r.get_vector<T>(kMaxPayload / sizeof(T)); }
};

// ---- The roles of an argument (tasks.def): the verifier's side holds the
// test's own argument; the worker's side is a tag, and the parameter's type.

template <class T>
struct In {
  const T& value;
};
template <class T>
struct Out {
  T* at;
};
// A reference, or a pointer that may be null (then nothing crosses either
// way). An InOut<const Ray> sends the ray and takes back its range.
template <class T>
struct InOut {
  T* at;
  bool pointer;
};
struct Generator {
  Rng& rng;
};
struct Callback {
  const std::function<Spectrum()>& next;
};
// An iterator that must be the first or past the last of the object's
// primitives: the whole range crosses, as the object says.
struct Begin {
  BVHAccel::PrimIter at;
};
struct End {
  BVHAccel::PrimIter at;
};

template <class T>
In<T> in(const T& v) {
  return {v};
}
template <class T>
Out<T> out(T* p) {
  return {p};
}
template <class T>
InOut<T> inout(T& v) {
  return {&v, false};
}
template <class T>
InOut<T> inout(T* p) {
  return {p, true};
}

struct InTag {};
struct OutTag {};
struct InOutTag {};
struct GeneratorTag {};
struct CallbackTag {};
struct RangeTag {};  // BEGIN and END

template <class... Args>
constexpr bool kTakesGenerator = (std::is_same_v<Args, Generator> || ...);
template <class... Tags>
constexpr bool kTagsGenerator = (std::is_same_v<Tags, GeneratorTag> || ...);

// A value of an argument or answer, with what the call's object says for the
// values that name objects.
template <class T, class Object>
void put_value(Writer& w, const T& v, Object& object) {
  if constexpr (std::is_same_v<T, Intersection>)
    object.put_hit(w, v);
  else if constexpr (std::is_same_v<T, const BVHNode*>)
    object.put_node(w, v);
  else
    Crossing<T>::put(w, v);
}
template <class T, class Object>
void get_value(Reader& r, T& v, Object& object) {
  if constexpr (std::is_same_v<T, Intersection>)
    object.get_hit(r, v);
  else if constexpr (std::is_same_v<T, const BVHNode*>)
    v = object.get_node(r);
  else
    v = Crossing<T>::get(r);
}

}  // namespace pt::boundary
