#pragma once
// The process boundary's wire (autograder/boundary/README.md): one pipe each
// way between the verifier (the graded tests, no student code) and the worker
// (the student's part, the framework, the solution of the other parts).
//
// Either side may call the other and, while it waits for the answer, serves
// the other's calls: the verifier calls a task function in the worker; the
// student's code there calls back a function that only the verifier has (a
// test's scripted radiance, Part 5's next_sample); that may call a task
// function again, and so on. A message is
//   u32 payload length | u8 kind | u16 call | u32 tag | payload
// where a request's tag is drawn at random and its answer repeats it. The
// worker's student code can write on the link too: an answer it forges
// before the worker's own is then either the wrong tag (it cannot know the
// tag without reading the worker's memory) or, right or wrong, followed by the
// worker's real answer, which the verifier's next call reads as a stale one.
// Either breaks the link.
// A payload is the call's values (crossing.h), copied as bytes where both
// ends are the same build (glm vectors, Camera, RenderSettings, Rng).
//
// Everything read here may come from hostile code: lengths are bounded, a
// payload must be read exactly to its end, and anything else breaks the link
// (LinkBroken), which the verifier treats as the worker's death.
#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "calls.h"

namespace pt::boundary {

constexpr uint32_t kMaxPayload = 64u << 20;

// A seed the worker's code cannot predict (request tags, which calls are replayed).
uint32_t unpredictable_seed();

// The link is unusable: the peer ended, or sent what no honest peer sends.
struct LinkBroken : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// ... because the peer is gone (the end of the stream, a write nobody reads).
struct LinkClosed : LinkBroken {
  using LinkBroken::LinkBroken;
};

class Writer {
 public:
  Writer() = default;
  explicit Writer(size_t capacity) { bytes_.reserve(capacity); }
  template <class T>
  Writer& put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "only plain values cross as bytes");
    const size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
    return *this;
  }
  Writer& put_bytes(const std::string& bytes) {
    bytes_.append(bytes);
    return *this;
  }
  Writer& put_string(const std::string& s) {
    put(static_cast<uint32_t>(s.size()));
    bytes_.append(s);
    return *this;
  }
  template <class T>
  Writer& put_vector(const std::vector<T>& v) {
    put(static_cast<uint64_t>(v.size()));
    for (const T& x : v) put(x);
    return *this;
  }
  const std::string& bytes() const { return bytes_; }
  // A u32 written later at `at` (a length known once what follows is written),
  // and what was written past `size` taken back.
  size_t size() const { return bytes_.size(); }
  void patch(size_t at, uint32_t value) { std::memcpy(bytes_.data() + at, &value, sizeof value); }
  void truncate(size_t size) { bytes_.resize(size); }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  explicit Reader(std::string&&) = delete;  // the bytes must outlive the reader
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>, "only plain values cross as bytes");
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  template <class... T>
  void get(T&... values) {
    ((values = get<T>()), ...);
  }
  std::string get_string(size_t max = 1 << 16);
  // The same, as a view into the message (valid while its bytes are).
  std::string_view get_view(size_t max);
  template <class T>
  std::vector<T> get_vector(size_t max) {
    const uint64_t n = get<uint64_t>();
    if (n > max || n > (bytes_.size() - at_) / sizeof(T)) throw LinkBroken("a list longer than the message");
    std::vector<T> v(static_cast<size_t>(n));
    for (T& x : v) x = get<T>();
    return v;
  }
  // Every payload is read exactly to its end.
  void finish() const;
  // All of the payload, as received; and all of it taken as read.
  std::string_view all() const { return bytes_; }
  void skip_to_end() { at_ = bytes_.size(); }

 private:
  void need(size_t n) const;
  std::string_view bytes_;
  size_t at_ = 0;
};

// What a call answers: a value, or an exception to throw on the caller's side.
enum class Kind : uint8_t { Request = 1, Return = 2, Throw = 3 };
enum class Thrown : uint8_t { Error = 0, NotImplemented = 1, OutOfMemory = 2 };

using Handler = std::function<void(Reader& args, Writer& result)>;

class Link {
 public:
  Link(int in_fd, int out_fd);

  void on(Call call, Handler handler);
  // Calls the peer and returns its answer's payload; serves the peer's calls
  // while it waits. An exception the peer's side threw is thrown here again
  // (pt::NotImplemented and std::bad_alloc as themselves, the rest as
  // std::runtime_error).
  std::string call(Call call, const Writer& args);
  // Serves calls until the peer closes its end (the worker's main loop).
  void serve();
  // The worker says it has reached main (its static initializers are done);
  // the verifier waits for that before its first call.
  void hello();
  void await_hello();

 private:
  struct Message {
    Kind kind;
    uint16_t call;
    uint32_t tag;
    std::string payload;
  };
  bool receive(Message& m);  // false at a clean end of the stream
  void send(Kind kind, uint16_t call, uint32_t tag, const std::string& payload);
  void handle(const Message& m);
  bool fill(size_t n);  // false at the end of the stream

  int in_, out_;
  std::vector<Handler> handlers_;
  std::mt19937 tags_;
  std::string buffer_;
  size_t start_ = 0;
};

}  // namespace pt::boundary
