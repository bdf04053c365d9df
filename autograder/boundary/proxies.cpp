// The verifier's copies of one part's task functions (README.md beside this
// file): each row of tasks.def of this verifier's part becomes the function
// as skeleton/ declares it, asking the worker (proxy.h).
#include "bvh_codec.h"
#include "proxy.h"
#include "rows.h"
#include "scene_codec.h"

#define IN(x) ::pt::boundary::in(x)
#define OUT(x) ::pt::boundary::out(x)
#define INOUT(x) ::pt::boundary::inout(x)
#define RNG(x) ::pt::boundary::Generator{x}
#define CALLBACK(x) ::pt::boundary::Callback{x}
#define BEGIN(x) ::pt::boundary::Begin{x}
#define END(x) ::pt::boundary::End{x}

#define PT_METHOD(part, task, call, R, Class, name, params, qualifier, Object, ...)                         \
  PT_ROWS_OF_PART_##part(R Class::name params qualifier {                                                  \
    return ::pt::boundary::ask_method<::pt::boundary::Call::call, ::pt::boundary::Object, R>(#Class "::" #name, \
                                                                                            *this, __VA_ARGS__); \
  })
#define PT_FUNCTION(part, task, call, R, name, params, ...)                                                 \
  PT_ROWS_OF_PART_##part(R name params {                                                                   \
    return ::pt::boundary::ask_function<::pt::boundary::Call::call, R>(#name, __VA_ARGS__);                 \
  })

namespace pt {
#include "tasks.def"
}  // namespace pt
