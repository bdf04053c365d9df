// The worker's servers of one part's task functions (README.md beside this
// file): each row of tasks.def of this worker's part answers its call with the
// student's function (serve.h).
#include "bvh_codec.h"
#include "rows.h"
#include "scene_codec.h"
#include "serve.h"

#define IN(x) ::pt::boundary::InTag{}
#define OUT(x) ::pt::boundary::OutTag{}
#define INOUT(x) ::pt::boundary::InOutTag{}
#define RNG(x) ::pt::boundary::GeneratorTag{}
#define CALLBACK(x) ::pt::boundary::CallbackTag{}
#define BEGIN(x) ::pt::boundary::RangeTag{}
#define END(x) ::pt::boundary::RangeTag{}

#define PT_METHOD(part, task, call, R, Class, name, params, qualifier, Object, ...)                   \
  PT_ROWS_OF_PART_##part(link.on(Call::call, serve<Object>(static_cast<R(Class::*) params qualifier>( \
                                                              &Class::name),                          \
                                                          __VA_ARGS__));)
#define PT_FUNCTION(part, task, call, R, name, params, ...) \
  PT_ROWS_OF_PART_##part(link.on(Call::call, serve<NoObject>(static_cast<R(*) params>(&name), __VA_ARGS__));)

namespace pt::boundary {

void serve_task_calls(Link& link) {
  serve_scene_definitions(link);
#include "tasks.def"
}

}  // namespace pt::boundary
