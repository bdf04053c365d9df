#pragma once
// The worker's side of a row of tasks.def: the call answered by the
// student's function, on the object and arguments rebuilt from what crossed
// (objects.h, crossing.h). A call with a generator answers in runs
// (generator_calls.h).
#include <functional>
#include <tuple>
#include <type_traits>
#include <utility>

#include "crossing.h"
#include "generator_calls.h"
#include "objects.h"
#include "worker_link.h"

namespace pt::boundary {

// One argument as the worker holds it, for a parameter of type P with a role
// (tasks.def): `arg(rng)` is what the student's function is passed, `fresh()`
// makes it as sent again (each call of a run starts from the same
// arguments), `reply` writes what comes back. By default: nothing to remake,
// nothing back.
struct Unchanging {
  void fresh() {}
  template <class Object>
  void reply(Writer&, Object&) const {}
};
template <class P, class Role>
class HeldArgument;

// IN: a value, or a const reference to one. A value is copied for each call;
// what a reference points at is made as sent again before each call, since a
// const reference still lets a task change mutable members (an intersection
// shortens a Ray's range), and a call of a run must see what a call made
// alone would.
template <class P>
class HeldArgument<P, InTag> : public Unchanging {
 public:
  template <class Object>
  HeldArgument(Reader& in, Object& object) {
    get_value(in, sent_, object);
    value_ = sent_;
  }
  void fresh() {
    if constexpr (std::is_reference_v<P>) value_ = sent_;
  }
  P arg(Rng*) { return value_; }

 private:
  std::decay_t<P> sent_{}, value_{};
};

// OUT: a pointer the function writes through; a fresh value each call.
template <class T>
class HeldArgument<T*, OutTag> {
 public:
  template <class Object>
  HeldArgument(Reader&, Object&) {}
  void fresh() { value_ = T{}; }
  T* arg(Rng*) { return &value_; }
  template <class Object>
  void reply(Writer& w, Object& object) const {
    put_value(w, value_, object);
  }

 private:
  T value_{};
};

// INOUT: a reference, a pointer that may be null, or a const Ray (its range).
template <class P>
class HeldArgument<P, InOutTag> {
  using T = std::remove_const_t<std::remove_pointer_t<std::remove_reference_t<P>>>;
  static constexpr bool kPointer = std::is_pointer_v<P>;

 public:
  template <class Object>
  HeldArgument(Reader& in, Object& object) {
    if constexpr (kPointer) present_ = in.get<uint8_t>() != 0;
    if (present_) get_value(in, sent_, object);
    value_ = sent_;
  }
  void fresh() { value_ = sent_; }
  P arg(Rng*) {
    if constexpr (kPointer)
      return present_ ? &value_ : nullptr;
    else
      return value_;
  }
  template <class Object>
  void reply(Writer& w, Object& object) const {
    if (!present_) return;
    if constexpr (std::is_same_v<P, const Ray&>)
      Crossing<Ray>::put_range(w, value_);
    else
      put_value(w, value_, object);
  }

 private:
  bool present_ = true;
  T sent_{}, value_{};
};

// RNG: the generator of the run's call.
template <>
class HeldArgument<Rng&, GeneratorTag> : public Unchanging {
 public:
  template <class Object>
  HeldArgument(Reader&, Object&) {}
  Rng& arg(Rng* rng) { return *rng; }
};

// CALLBACK: each call of the function is a call back to the verifier's.
template <>
class HeldArgument<const std::function<Spectrum()>&, CallbackTag> : public Unchanging {
 public:
  template <class Object>
  HeldArgument(Reader&, Object&) {}
  const std::function<Spectrum()>& arg(Rng*) { return next_; }

 private:
  std::function<Spectrum()> next_ = [] {
    const std::string answer = worker_link().call(Call::NextSample, Writer());
    Reader sample(answer);
    const auto value = sample.get<Spectrum>();
    sample.finish();
    return value;
  };
};

// BEGIN, END: the object's whole range, which the object builds over itself.
template <>
class HeldArgument<BVHAccel::PrimIter, RangeTag> : public Unchanging {
 public:
  template <class Object>
  HeldArgument(Reader&, Object&) {}
  BVHAccel::PrimIter arg(Rng*) { return {}; }
};

template <class R, class Object>
void put_result(Writer& w, const R& result, Object& object) {
  if constexpr (std::is_same_v<R, std::unique_ptr<BVHNode>>)
    object.put_tree(w);
  else
    Crossing<R>::put(w, result);
}

template <class Fn>
struct Signature;
template <class R, class C, class... P>
struct Signature<R (C::*)(P...) const> {
  using Result = R;
  using Params = std::tuple<P...>;
};
template <class R, class C, class... P>
struct Signature<R (C::*)(P...)> {
  using Result = R;
  using Params = std::tuple<P...>;
};
template <class R, class... P>
struct Signature<R (*)(P...)> {
  using Result = R;
  using Params = std::tuple<P...>;
};

template <class Object, class Fn, class... P, class... Tags>
void answer(Fn fn, std::tuple<P...>*, Reader& in, Writer& out, Tags...) {
  using R = typename Signature<Fn>::Result;
  typename Object::Held object(in);
  std::tuple<HeldArgument<P, Tags>...> args{HeldArgument<P, Tags>(in, object)...};
  auto once = [&](Rng* rng, Writer& w) {
    std::apply([](auto&... a) { (a.fresh(), ...); }, args);
    const R result = std::apply([&](auto&... a) { return object.invoke(fn, a.arg(rng)...); }, args);
    put_result(w, result, object);
    std::apply([&](auto&... a) { (a.reply(w, object), ...); }, args);
    object.put_after(w);
  };
  if constexpr (kTagsGenerator<Tags...>)
    answer_run(in, out, [&](Rng& rng, Writer& w) { once(&rng, w); });
  else
    once(nullptr, out);
}

// The handler of a row: `fn` the student's function, `tags` its arguments' roles.
template <class Object, class Fn, class... Tags>
Handler serve(Fn fn, Tags... tags) {
  static_assert(std::tuple_size_v<typename Signature<Fn>::Params> == sizeof...(Tags),
                "a row of tasks.def names a role for each parameter");
  return [fn, tags...](Reader& in, Writer& out) {
    answer<Object>(fn, static_cast<typename Signature<Fn>::Params*>(nullptr), in, out, tags...);
  };
}

}  // namespace pt::boundary
