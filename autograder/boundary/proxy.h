#pragma once
// The verifier's side of a row of tasks.def: the task function as the tests
// call it, asking the worker. Its object and arguments go (objects.h,
// crossing.h), the answer comes back with what the arguments take back, and
// a call with a generator is asked for in runs, its states checked to move
// forward and a share of its answers replayed (generator_calls.h). Every row
// gets these by being in the table.
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "crossing.h"
#include "generator_calls.h"
#include "objects.h"
#include "verifier_link.h"

namespace pt::boundary {

template <class T, class Object>
void put_argument(Writer& w, const In<T>& a, Object& object) {
  put_value(w, a.value, object);
}
template <class T, class Object>
void put_argument(Writer& w, const InOut<T>& a, Object& object) {
  if (a.pointer) {
    w.put(static_cast<uint8_t>(a.at != nullptr));
    if (!a.at) return;
  }
  put_value(w, static_cast<const T&>(*a.at), object);
}
template <class Role, class Object>
void put_argument(Writer&, const Role&, Object&) {}  // OUT, RNG, CALLBACK, BEGIN, END: nothing goes

template <class T, class Object>
void take_back(Reader& r, const Out<T>& a, Object& object) {
  get_value(r, *a.at, object);
}
template <class T, class Object>
void take_back(Reader& r, const InOut<T>& a, Object& object) {
  if (!a.at) return;
  if constexpr (std::is_same_v<T, const Ray>)
    Crossing<Ray>::get_range(r, *a.at);
  else
    get_value(r, *a.at, object);
}
template <class Role, class Object>
void take_back(Reader&, const Role&, Object&) {}  // IN, RNG, CALLBACK, BEGIN, END: nothing comes back

// BEGIN and END are the object's to check.
template <class Object>
void check_range(const Begin& a, Object& object) {
  object.whole(a.at, true);
}
template <class Object>
void check_range(const End& a, Object& object) {
  object.whole(a.at, false);
}
template <class Role, class Object>
void check_range(const Role&, Object&) {}

// The argument of role `Role` (RNG, CALLBACK), if the call has one.
template <class Role, class... Args>
const Role* role_in(const Args&... args) {
  const Role* found = nullptr;
  auto take = [&](const auto& a) {
    if constexpr (std::is_same_v<std::decay_t<decltype(a)>, Role>) found = &a;
  };
  (take(args), ...);
  return found;
}

template <class R, class Object>
R get_result(Reader& r, Object& object) {
  if constexpr (std::is_same_v<R, std::unique_ptr<BVHNode>>)
    return object.get_tree(r);
  else
    return Crossing<R>::get(r);
}

// The call `call` (`task` names it in failure messages) on `object`, with
// the link held since the object was made (a scene sent for this call is the
// worker's scene until it answers).
template <Call call, class Object, class R, class... Args>
R ask(const char* task, typename Object::Sent& object, Args... args) {
  (check_range(args, object), ...);
  Writer request(256);
  object.put(request);
  (put_argument(request, args, object), ...);
  std::optional<Scoped<const std::function<Spectrum()>*>> samples;
  if (const auto* callback = role_in<Callback>(args...)) samples.emplace(g_next_sample, &callback->next);
  std::string one;
  std::string_view answer;
  if constexpr (kTakesGenerator<Args...>) {
    thread_local GeneratorCalls runs(call, task, Object::kCallsBack);
    answer = read_answer([&] { return runs.next(request, role_in<Generator>(args...)->rng, call_worker); });
  } else {
    one = call_worker(call, request);
    answer = one;
  }
  R result = read_answer([&] {
    Reader r(answer);
    R value = get_result<R>(r, object);
    (take_back(r, args, object), ...);
    object.take_after(r);
    r.finish();
    return value;
  });
  object.after_call();
  return result;
}

template <Call call, class Object, class R, class Self, class... Args>
R ask_method(const char* task, Self& self, Args... args) {
  const auto link = hold_link();
  typename Object::Sent object(self);
  return ask<call, Object, R>(task, object, args...);
}

template <Call call, class R, class... Args>
R ask_function(const char* task, Args... args) {
  const auto link = hold_link();
  NoObject::Sent object;
  return ask<call, NoObject, R>(task, object, args...);
}

}  // namespace pt::boundary
