// Hostile: across the process boundary the tests count a traversal's work by
// the primitive tests it calls back to the verifier for (autograder/boundary/
// bvh_codec.h); once, by a log of them in its answer. Before the solution's
// traversal answers, this one writes on the worker's link (descriptor 3) an
// answer of its own: a hit at t = 1 on primitive 0, with no primitive test
// made, no work at all. The format is public (the release ships the grader's
// source); the request's tag is not, and it guesses 0. The verifier reads an
// answer whose tag is not its call's, or, had the guess been right, the real
// answer as a stale one at its next call: the link breaks, and each test that
// asks for a closest hit costs only itself.
#include <cstdint>
#include <cstring>
#include <string>

// <unistd.h> is not allowed in the grading kit: write() declared here.
extern "C" long write(int fd, const void* bytes, unsigned long n);

namespace {
template <class T>
void put(std::string& s, const T& v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

void forge_closest_hit() {
  std::string payload;
  put(payload, uint8_t(1));                    // hit
  put(payload, 0.0);                           // min_t
  put(payload, 1.0);                           // max_t
  put(payload, 1.0);                           // t
  put(payload, int64_t(0));                    // primitive 0
  std::string message(11, '\0');
  const uint32_t length = static_cast<uint32_t>(payload.size());
  const uint16_t call = 203;                   // BvhIntersect (tasks.def)
  const uint32_t tag = 0;                      // a guess
  std::memcpy(&message[0], &length, 4);
  message[4] = 2;                              // an answer
  std::memcpy(&message[5], &call, 2);
  std::memcpy(&message[7], &tag, 4);
  message += payload;
  ::write(3, message.data(), message.size());
}
}  // namespace
