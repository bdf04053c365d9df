// Hostile: Part 3's estimators answer in runs (autograder/boundary/
// generator_calls.h). Before it throws as the stubs do, each task writes on the
// worker's link (descriptor 3) an answer of its own making: a run of 65,536
// "estimates" of exactly the radiance the mean tests expect at their most
// common receiver, for each of the estimators' calls, more than any run the
// verifier asks for. Whatever the verifier reads first is an answer to a call
// it did not make or a run longer than it asked for: the link breaks, and
// each test costs only itself.
#include <cstdint>
#include <cstring>
#include <string>

#include "core/not_implemented.h"
#include "core/rng.h"
#include "core/vec.h"

// <unistd.h> is not allowed in the grading kit: write() declared here.
extern "C" long write(int fd, const void* bytes, unsigned long n);

namespace {
void forge_runs() {
  for (uint16_t call = 300; call <= 306; ++call) {  // Part 3's rows of tasks.def
    std::string payload;
    const uint32_t n = 1u << 16;
    payload.append(reinterpret_cast<const char*>(&n), sizeof n);
    const pt::Spectrum value(0.25);
    const pt::Rng state;
    const uint32_t size = sizeof value;
    for (uint32_t i = 0; i < n; ++i) {
      payload.append(reinterpret_cast<const char*>(&size), sizeof size);
      payload.append(reinterpret_cast<const char*>(&value), sizeof value);
      payload.append(reinterpret_cast<const char*>(&state), sizeof state);
    }
    std::string message(11, '\0');  // its tag, a guess: 0
    const uint32_t length = static_cast<uint32_t>(payload.size());
    std::memcpy(&message[0], &length, 4);
    message[4] = 2;  // an answer
    std::memcpy(&message[5], &call, 2);
    message += payload;
    ::write(3, message.data(), message.size());
  }
}
}  // namespace
// Every stub task runs the attack where it would throw.
#define NotImplemented(task) (forge_runs(), NotImplemented(task))
