#include "wire.h"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <new>

#include "core/not_implemented.h"

namespace pt::boundary {
namespace {

constexpr size_t kHeader = 11;  // u32 length, u8 kind, u16 call, u32 tag
const std::string kNotImplementedPrefix = "not implemented: ";

}  // namespace

std::string Reader::get_string(size_t max) { return std::string(get_view(max)); }

std::string_view Reader::get_view(size_t max) {
  const uint32_t n = get<uint32_t>();
  if (n > max) throw LinkBroken("a string longer than " + std::to_string(max) + " bytes");
  need(n);
  const std::string_view s = bytes_.substr(at_, n);
  at_ += n;
  return s;
}

void Reader::need(size_t n) const {
  if (n > bytes_.size() - at_) throw LinkBroken("a message shorter than its call's values");
}

void Reader::finish() const {
  if (at_ != bytes_.size()) throw LinkBroken("a message longer than its call's values");
}

// The system's entropy or, where a sandbox leaves none (no getrandom, no
// /dev/urandom), the clock and this process's randomised addresses.
uint32_t unpredictable_seed() {
  try {
    return std::random_device()();
  } catch (const std::exception&) {
    const auto now = static_cast<uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
    const auto here = reinterpret_cast<uintptr_t>(&now) ^ reinterpret_cast<uintptr_t>(&unpredictable_seed);
    return static_cast<uint32_t>(now ^ (now >> 32) ^ here ^ (here >> 32));
  }
}

Link::Link(int in_fd, int out_fd) : in_(in_fd), out_(out_fd), tags_(unpredictable_seed()) {}

void Link::on(Call call, Handler handler) {
  const size_t i = static_cast<size_t>(call);
  if (handlers_.size() <= i) handlers_.resize(i + 1);
  handlers_[i] = std::move(handler);
}

bool Link::fill(size_t n) {
  if (start_ > 0 && start_ == buffer_.size()) {
    buffer_.clear();
    start_ = 0;
  }
  while (buffer_.size() - start_ < n) {
    char chunk[1 << 16];
    const ssize_t got = ::read(in_, chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw LinkBroken(std::string("reading the link: ") + std::strerror(errno));
    if (got == 0) return false;
    buffer_.append(chunk, static_cast<size_t>(got));
  }
  return true;
}

bool Link::receive(Message& m) {
  if (!fill(kHeader)) {
    if (buffer_.size() == start_) return false;  // ended between messages
    throw LinkClosed("the other side closed the link in the middle of a message");
  }
  uint32_t length;
  std::memcpy(&length, buffer_.data() + start_, 4);
  const uint8_t kind = static_cast<uint8_t>(buffer_[start_ + 4]);
  std::memcpy(&m.call, buffer_.data() + start_ + 5, 2);
  std::memcpy(&m.tag, buffer_.data() + start_ + 7, 4);
  if (length > kMaxPayload) throw LinkBroken("a message of " + std::to_string(length) + " bytes");
  if (kind < 1 || kind > 3) throw LinkBroken("a message of unknown kind " + std::to_string(kind));
  m.kind = static_cast<Kind>(kind);
  if (!fill(kHeader + length)) throw LinkClosed("the other side closed the link in the middle of a message");
  m.payload.assign(buffer_, start_ + kHeader, length);
  start_ += kHeader + length;
  return true;
}

void Link::send(Kind kind, uint16_t call, uint32_t tag, const std::string& payload) {
  std::string bytes(kHeader, '\0');
  const uint32_t length = static_cast<uint32_t>(payload.size());
  std::memcpy(bytes.data(), &length, 4);
  bytes[4] = static_cast<char>(kind);
  std::memcpy(bytes.data() + 5, &call, 2);
  std::memcpy(bytes.data() + 7, &tag, 4);
  bytes += payload;
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(out_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EPIPE) throw LinkClosed("the other side closed the link");
    if (n <= 0) throw LinkBroken(std::string("writing the link: ") + std::strerror(errno));
    done += static_cast<size_t>(n);
  }
}

void Link::handle(const Message& m) {
  Writer result, thrown;
  const auto fail = [&](Thrown what, const char* text) { thrown.put(what).put_string(text); };
  try {
    if (m.call >= handlers_.size() || !handlers_[m.call])
      throw std::runtime_error("the other side asked for call " + std::to_string(m.call) + ", which this side does not serve");
    Reader args(m.payload);
    handlers_[m.call](args, result);
    args.finish();
  } catch (const LinkBroken&) {
    throw;
  } catch (const NotImplemented& e) {
    fail(Thrown::NotImplemented, e.what());
  } catch (const std::bad_alloc& e) {
    fail(Thrown::OutOfMemory, e.what());
  } catch (const std::exception& e) {
    fail(Thrown::Error, e.what());
  } catch (...) {
    fail(Thrown::Error, "an exception that is not a std::exception");
  }
  const bool threw = thrown.size() > 0;
  send(threw ? Kind::Throw : Kind::Return, m.call, m.tag, threw ? thrown.bytes() : result.bytes());
}

std::string Link::call(Call call, const Writer& args) {
  const uint32_t tag = static_cast<uint32_t>(tags_());
  send(Kind::Request, static_cast<uint16_t>(call), tag, args.bytes());
  for (Message m;;) {
    if (!receive(m)) throw LinkClosed("the other side closed the link before answering");
    if (m.kind == Kind::Request) {
      handle(m);
      continue;
    }
    if (m.call != static_cast<uint16_t>(call)) throw LinkBroken("an answer to a call that was not made");
    if (m.tag != tag) throw LinkBroken("an answer that is not this call's (its tag is another's: forged, or stale)");
    if (m.kind == Kind::Return) return std::move(m.payload);
    Reader r(m.payload);
    const auto what = r.get<Thrown>();
    std::string text = r.get_string();
    r.finish();
    if (what == Thrown::NotImplemented) {
      if (text.rfind(kNotImplementedPrefix, 0) == 0) text.erase(0, kNotImplementedPrefix.size());
      throw NotImplemented(text);
    }
    if (what == Thrown::OutOfMemory) throw std::bad_alloc();
    throw std::runtime_error(text);
  }
}

void Link::hello() { send(Kind::Return, 0, 0, ""); }

void Link::await_hello() {
  Message m;
  if (!receive(m)) throw LinkClosed("the worker ended before its main started");
  if (m.kind != Kind::Return || m.call != 0 || m.tag != 0 || !m.payload.empty()) throw LinkBroken("the worker did not say hello");
}

void Link::serve() {
  for (Message m; receive(m);) {
    if (m.kind != Kind::Request) throw LinkBroken("an answer to a call that was not made");
    handle(m);
  }
}

}  // namespace pt::boundary
