#pragma once
// The calls that cross the boundary, by number: a task function's is made
// from its row of tasks.def (its part's hundred and its place among the
// part's rows: 203 is Part 2's fourth row), so that a row added at the end of
// its part leaves every other number alone; the few calls that are no task's
// are numbered here.
#include <cstdint>

namespace pt::boundary {
namespace rows {

#define PT_METHOD(part, task, call, ...) call,
#define PT_FUNCTION(part, task, call, ...) call,
enum Row : int {
#include "tasks.def"
  kRows
};
#undef PT_METHOD
#undef PT_FUNCTION

#define PT_METHOD(part, ...) part,
#define PT_FUNCTION(part, ...) part,
constexpr int kPartOf[] = {
#include "tasks.def"
};
#undef PT_METHOD
#undef PT_FUNCTION

constexpr uint16_t number(Row row) {
  int place = 0;
  for (int i = 0; i < row; ++i) place += kPartOf[i] == kPartOf[row];
  return static_cast<uint16_t>(kPartOf[row] * 100 + place);
}

}  // namespace rows

enum class Call : uint16_t {
#define PT_METHOD(part, task, call, ...) call = rows::number(rows::call),
#define PT_FUNCTION(part, task, call, ...) call = rows::number(rows::call),
#include "tasks.def"
#undef PT_METHOD
#undef PT_FUNCTION
  // A scene crosses once, then calls name it (scene_codec.h).
  DefineScene = 900,
  // Calls back into the verifier, made by the worker while it answers.
  EstRadiance = 1000,  // PathTracer::est_radiance_global_illumination of the verifier's tracer (PixelTracer)
  NextSample,          // the next_sample passed to sample_adaptively (CALLBACK)
  TestPrimitive,       // a primitive test of a BVH's handle, made on the verifier's primitive (Tree)
};

}  // namespace pt::boundary
