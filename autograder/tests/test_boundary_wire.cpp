// The process boundary's wire (boundary/wire.h): what an honest peer sends
// arrives whole, callbacks nest, exceptions cross with their kind, and every
// malformed message a hostile worker could write breaks the link instead of
// being read past its end or allocated for.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <string>
#include <thread>

#include "core/not_implemented.h"
#include "wire.h"

namespace pt::boundary {
namespace {

// Two pipes: side A reads what side B writes and the other way round.
struct PipePair {
  int a_in = -1, a_out = -1, b_in = -1, b_out = -1;
  PipePair() {
    int ab[2], ba[2];
    if (::pipe2(ab, O_CLOEXEC) != 0 || ::pipe2(ba, O_CLOEXEC) != 0) throw std::runtime_error("pipe");
    a_out = ab[1], b_in = ab[0], b_out = ba[1], a_in = ba[0];
  }
  ~PipePair() {
    for (int fd : {a_in, a_out, b_in, b_out})
      if (fd >= 0) ::close(fd);
  }
  // Side B stops writing; what it wrote is still read, then the end of the
  // stream (its read end stays open: A's request has somewhere to go).
  void close_b() {
    ::close(b_out);
    b_out = -1;
  }
};

// Raw bytes as a hostile peer would write them: header, then payload.
std::string message(uint32_t length, uint8_t kind, uint16_t call, const std::string& payload, uint32_t tag = 0) {
  std::string bytes(11, '\0');
  std::memcpy(bytes.data(), &length, 4);
  bytes[4] = static_cast<char>(kind);
  std::memcpy(bytes.data() + 5, &call, 2);
  std::memcpy(bytes.data() + 7, &tag, 4);
  return bytes + payload;
}

void write_raw(int fd, const std::string& bytes) { ASSERT_EQ(::write(fd, bytes.data(), bytes.size()), ssize_t(bytes.size())); }

TEST(BoundaryWire, ACallItsCallbackAndItsAnswer) {
  PipePair p;
  Link verifier(p.a_in, p.a_out), worker(p.b_in, p.b_out);
  verifier.on(Call::NextSample, [](Reader&, Writer& out) { out.put(2.5); });
  worker.on(Call::SampleAdaptively, [&worker](Reader& in, Writer& out) {
    const int n = in.get<int>();
    double sum = 0;
    for (int i = 0; i < n; ++i) {  // calls back into the verifier while it waits
      const std::string answer = worker.call(Call::NextSample, Writer());
      Reader sample(answer);
      sum += sample.get<double>();
      sample.finish();
    }
    out.put(sum);
  });
  std::thread serving([&worker] { worker.serve(); });
  Writer args;
  args.put(4);
  const std::string answer = verifier.call(Call::SampleAdaptively, args);
  Reader result(answer);
  EXPECT_EQ(result.get<double>(), 10.0) << "four callbacks of 2.5";
  result.finish();
  ::close(p.a_out);  // the worker's serve() ends at the end of its stream
  p.a_out = -1;
  serving.join();
}

TEST(BoundaryWire, ExceptionsCrossWithTheirKind) {
  PipePair p;
  Link verifier(p.a_in, p.a_out), worker(p.b_in, p.b_out);
  worker.on(Call::GenerateRay, [](Reader&, Writer&) -> void { throw NotImplemented("P1T1 Camera::generate_ray"); });
  worker.on(Call::SphereTest, [](Reader&, Writer&) -> void { throw std::out_of_range("vector::at"); });
  worker.on(Call::SphereHas, [](Reader&, Writer&) -> void { throw 42; });
  // A build that runs out of the address space it was given (Part 2's hidden
  // test catches std::bad_alloc by name).
  worker.on(Call::BuildBvh, [](Reader&, Writer&) -> void { throw std::bad_alloc(); });
  std::thread serving([&worker] { worker.serve(); });
  try {
    verifier.call(Call::GenerateRay, Writer());
    ADD_FAILURE() << "no exception";
  } catch (const NotImplemented& e) {
    EXPECT_STREQ(e.what(), "not implemented: P1T1 Camera::generate_ray") << "the task named once, as in-process";
  }
  EXPECT_THROW(
      try { verifier.call(Call::SphereTest, Writer()); } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "vector::at");
        throw;
      },
      std::runtime_error);
  EXPECT_THROW(verifier.call(Call::SphereHas, Writer()), std::runtime_error);
  EXPECT_THROW(verifier.call(Call::BuildBvh, Writer()), std::bad_alloc);
  ::close(p.a_out);
  p.a_out = -1;
  serving.join();
}

// Each case: bytes a hostile worker sends as the answer to GenerateRay; the
// verifier must throw LinkBroken (not read past the message, not allocate
// what the header claims, not take an answer to another call).
struct Malformed {
  const char* what;
  std::string bytes;
  bool closed;  // LinkClosed: the stream ended
};

TEST(BoundaryWire, MalformedAnswersBreakTheLink) {
  const uint16_t call = static_cast<uint16_t>(Call::GenerateRay);
  const Malformed cases[] = {
      {"a length past the limit", message(kMaxPayload + 1, 2, call, ""), false},
      {"an unknown kind", message(0, 9, call, ""), false},
      {"an answer to a call not made", message(0, 2, call + 1, ""), false},
      {"an answer with another call's tag", message(0, 2, call, "", 0x5eed), false},
      {"a thrown answer too short for its text", message(3, 3, call, std::string("\0\xff\xff", 3)), false},
      {"the stream ending inside a header", std::string("\x10\0\0", 3), true},
      {"the stream ending inside a payload", message(16, 2, call, "12345678"), true},
  };
  for (const Malformed& c : cases) {
    PipePair p;
    Link verifier(p.a_in, p.a_out);
    write_raw(p.b_out, c.bytes);
    p.close_b();
    try {
      verifier.call(Call::GenerateRay, Writer());
      ADD_FAILURE() << c.what << ": accepted";
    } catch (const LinkClosed&) {
      EXPECT_TRUE(c.closed) << c.what << ": taken for the end of the stream";
    } catch (const LinkBroken&) {
      EXPECT_FALSE(c.closed) << c.what << ": not taken for the end of the stream";
    }
  }
}

// The worker's student code writes on the link an answer of its own making
// before the worker's real one. Even one that guessed the request's tag (here
// it is read off the wire, as only a read of the worker's memory could) is
// followed by the real answer, which the next call meets as a stale one.
TEST(BoundaryWire, AForgedAnswerBreaksTheLinkByTheNextCall) {
  PipePair p;
  Link verifier(p.a_in, p.a_out);
  std::thread worker([&p] {
    for (int i = 0; i < 2; ++i) {
      char header[11];
      if (::read(p.b_in, header, sizeof header) != ssize_t(sizeof header)) return;  // the request (no payload)
      uint16_t call;
      uint32_t tag;
      std::memcpy(&call, header + 5, 2);
      std::memcpy(&tag, header + 7, 4);
      Writer forged, real;
      forged.put(1.0);
      real.put(2.0);
      const std::string both = message(8, 2, call, forged.bytes(), tag) + message(8, 2, call, real.bytes(), tag);
      if (::write(p.b_out, both.data(), both.size()) != ssize_t(both.size())) return;
    }
  });
  const std::string first = verifier.call(Call::NextSample, Writer());
  EXPECT_EQ(Reader(first).get<double>(), 1.0) << "the forged answer had the right tag and came first";
  EXPECT_THROW(verifier.call(Call::NextSample, Writer()), LinkBroken) << "the real answer to the first call, stale";
  p.close_b();
  worker.join();
}

TEST(BoundaryWire, AnAnswerIsReadExactlyToItsEnd) {
  Writer w;
  w.put(1.0).put(2.0);
  const std::string bytes = w.bytes();
  Reader short_read(bytes);
  short_read.get<double>();
  EXPECT_THROW(short_read.finish(), LinkBroken) << "a message longer than its call's values";
  Reader long_read(bytes);
  long_read.get<double>();
  long_read.get<double>();
  EXPECT_THROW(long_read.get<double>(), LinkBroken) << "a message shorter than its call's values";
}

TEST(BoundaryWire, AListCannotClaimMoreThanTheMessageHolds) {
  Writer w;
  w.put(uint64_t(1) << 40);  // a trillion ints claimed, none sent
  const std::string bytes = w.bytes();
  Reader r(bytes);
  EXPECT_THROW(r.get_vector<int>(uint64_t(1) << 41), LinkBroken) << "no allocation of what the count claims";
  Writer s;
  s.put(uint32_t(1000)).put('x');
  const std::string text = s.bytes();
  Reader rs(text);
  EXPECT_THROW(rs.get_string(), LinkBroken) << "a string longer than the message";
}

TEST(BoundaryWire, AWorkerThatSaysNoHelloIsNotServed) {
  PipePair p;
  Link verifier(p.a_in, p.a_out);
  write_raw(p.b_out, message(0, 2, 7, ""));  // an answer, but not the hello
  EXPECT_THROW(verifier.await_hello(), LinkBroken);
  PipePair q;
  Link verifier2(q.a_in, q.a_out);
  q.close_b();
  EXPECT_THROW(verifier2.await_hello(), LinkClosed) << "a worker that died before main";
}

}  // namespace
}  // namespace pt::boundary
