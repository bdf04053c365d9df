#pragma once
// What each part's task file may call beyond its own code, the framework and
// the C++ library: the one table pt-link-guard reads (compile/link_guard.cpp).
//
// A part is graded with the other parts' solutions linked beside it, so a
// task file could hand a task to another part's solution: Part 1's pixel
// loop is Part 5's adaptive loop with its stopping rule off (P1T2 scored 4.5
// that way). A task file may call another part's solution only where its
// handout specifies it (the handouts' "What you use" tables); any other
// reference to a function the other parts' solutions define is refused.
// Virtual calls (a primitive's intersect, a BSDF's sample_f through
// isect.bsdf, est_radiance_global_illumination from the pixel loop) go
// through the framework's objects and name no solution symbol: they are the
// framework's interface, not a reference to a solution.
namespace pt::grade {

struct SolutionCall {
  int part;              // the calling part
  const char* function;  // the start of the callee's demangled name, up to its "("
  const char* why;       // where its handout says so
};

inline constexpr SolutionCall kSolutionCalls[] = {
    {4, "pt::PathTracer::zero_bounce_radiance(", "P3T2, bounce 0 (handouts/part4.md)"},
    {4, "pt::PathTracer::one_bounce_radiance(", "P3T5, direct light at every vertex (handouts/part4.md)"},
    {4, "pt::DiffuseBSDF::sample_f(", "P3T1, the next bounce's direction (handouts/part4.md)"},
    {5, "pt::Camera::generate_ray(", "P1T1, the camera rays of the pixel loop (handouts/part5.md)"},
};

// Framework functions that are a task's own answer: the budgeted renderer's
// allocator does P5T3's work, so no task file may call it.
struct TaskAnswer {
  const char* function;  // the start of its demangled name
  const char* task;
};

inline constexpr TaskAnswer kTaskAnswers[] = {{"pt::allocate_counts(", "P5T3"}, {"pt::pooled_relative_sd(", "P5T3"}};

}  // namespace pt::grade
