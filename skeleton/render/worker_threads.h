#pragma once
// Threads with a stack size of our choosing. std::thread takes the system's
// default (8 MiB on Linux, from `ulimit -s`; 512 KiB on macOS), which the
// recursive path estimator can outgrow (render/limits.h).
#include <cstddef>
#include <functional>
#include <string>

namespace pt {

// Runs work() (which must not throw) on `count` new threads with
// `stack_bytes` of stack each and waits for them all. When the system refuses a thread (a process or user
// limit), runs on those it got: returns how many ran. Returns 0 when not one
// could start; then work() never ran and *error says why.
int run_on_threads(int count, size_t stack_bytes, const std::function<void()>& work, std::string* error);

}  // namespace pt
