#include "io/collada_document.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/decimal_text.h"
#include "io/input_file.h"
#include "io/scene_text.h"
#include "io/scene_loader.h"

namespace pt {

namespace {

bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Calls f(token, index) for each whitespace-separated token of s.
template <class F>
void for_each_token(std::string_view s, F f) {
  size_t i = 0, index = 0;
  while (true) {
    while (i < s.size() && is_xml_space(s[i])) ++i;
    if (i == s.size()) return;
    size_t j = i;
    while (j < s.size() && !is_xml_space(s[j])) ++j;
    f(s.substr(i, j - i), index++);
    i = j;
  }
}

// XML Schema numbers may carry a '+', which from_chars does not take.
std::string_view without_plus(std::string_view t) {
  return t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+' ? t.substr(1) : t;
}

std::string ordinal(size_t index) { return "value " + std::to_string(index + 1); }

XmlNode first_element(XmlNode n) {
  while (n && n.type() != pugi::node_element) n = n.next_sibling();
  return n;
}

// The element after n in document order within root's subtree (empty at the end).
XmlNode next_element(XmlNode n, XmlNode root) {
  if (XmlNode c = first_element(n.first_child())) return c;
  for (; n && n != root; n = n.parent())
    if (XmlNode s = first_element(n.next_sibling())) return s;
  return XmlNode();
}

}  // namespace

ColladaDocument::ColladaDocument(std::string path, std::vector<std::string>* warnings, size_t max_warnings)
    : path_(std::move(path)), warnings_(warnings), max_warnings_(max_warnings) {
  // A COLLADA scene carries its meshes: the mesh bound, checked before reading.
  const std::string bytes = read_input_file(path_, kMaxMeshFileBytes, "a COLLADA scene");
  // parse_default expands only the five predefined entities and character
  // references (no DTD entities), so no file can blow up in memory here.
  pugi::xml_parse_result parsed = doc_.load_buffer(bytes.data(), bytes.size(), pugi::parse_default);
  if (!parsed) {
    TextPosition at = text_position(bytes, size_t(std::max<ptrdiff_t>(parsed.offset, 0)));
    throw SceneError(path_ + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                     ": XML syntax error: " + parsed.description());
  }
  XmlNode r = root();
  if (std::strcmp(r.name(), "COLLADA") != 0)
    fail(r, "not a COLLADA document (the root element is <" + quoted(r.name()) + ">, expected <COLLADA>)");

  // Every id in the document, walked without recursion (any depth is safe).
  for (XmlNode n = r; n; n = next_element(n, r)) {
    if (pugi::xml_attribute id = n.attribute("id")) {
      auto [it, inserted] = ids_.emplace(std::string_view(id.value()), n);
      if (!inserted)
        throw SceneError(path_ + ": " + path_of(n, false) + ": duplicate id '" + quoted(id.value()) + "' (also on " +
                         path_of(it->second, false) + ")");
    }
  }
}

std::string ColladaDocument::quoted(std::string_view s) {
  std::string out;
  for (char ch : s.substr(0, 60)) {
    unsigned char c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f && c != '\'' && c != '\\') {
      out += ch;
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (s.size() > 60) out += "...";
  return out;
}

std::string ColladaDocument::path_of(XmlNode e, bool by_id) {
  std::vector<std::string> parts;
  for (; e && e.type() == pugi::node_element; e = e.parent()) {
    std::string part = quoted(e.name());
    if (pugi::xml_attribute id = e.attribute("id"); id && by_id) {
      part += "[@id='" + quoted(id.value()) + "']";
    } else if (e.previous_sibling(e.name()) || e.next_sibling(e.name())) {
      size_t position = 1;
      for (XmlNode s = e.previous_sibling(e.name()); s; s = s.previous_sibling(e.name())) ++position;
      part += "[" + std::to_string(position) + "]";
    }
    parts.push_back(std::move(part));
  }
  std::string path;
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) path += "/" + *it;
  return path.empty() ? "/" : path;
}

void ColladaDocument::fail(XmlNode at, const std::string& message) const {
  throw SceneError(path_ + ": " + path_of(at) + ": " + message);
}

void ColladaDocument::warn(XmlNode at, const std::string& message) {
  if (warnings_->size() >= max_warnings_) {
    ++dropped_warnings_;
    return;
  }
  warnings_->push_back(path_of(at) + ": " + message);
}

void ColladaDocument::finish() {
  if (dropped_warnings_ > 0)
    warnings_->push_back("... " + std::to_string(dropped_warnings_) + " more warnings not shown");
  dropped_warnings_ = 0;
}

XmlNode ColladaDocument::resolve(XmlNode at, const char* attribute, const char* kind) const {
  pugi::xml_attribute a = at.attribute(attribute);
  if (!a) fail(at, std::string("missing attribute ") + attribute + " (a reference to a <" + kind + ">)");
  std::string_view ref = a.value();
  if (ref.empty() || ref[0] != '#')
    fail(at, std::string(attribute) + "=\"" + quoted(ref) + "\": only references within the file (\"#id\") are supported");
  auto it = ids_.find(ref.substr(1));
  if (it == ids_.end()) fail(at, std::string(attribute) + "=\"" + quoted(ref) + "\": the file has no element with this id");
  if (std::strcmp(it->second.name(), kind) != 0)
    fail(at, std::string(attribute) + "=\"" + quoted(ref) + "\" refers to a <" + quoted(it->second.name()) +
                 ">, expected a <" + kind + ">");
  return it->second;
}

XmlNode ColladaDocument::child(XmlNode e, const char* name) const {
  XmlNode c = e.child(name);
  if (!c) fail(e, std::string("missing <") + name + ">");
  return c;
}

std::string_view ColladaDocument::text(XmlNode e, std::string* storage) const {
  std::string_view first;
  size_t pieces = 0;
  for (XmlNode c : e.children()) {
    if (c.type() == pugi::node_element) fail(c, std::string("unexpected element inside <") + quoted(e.name()) + ">");
    if (c.type() != pugi::node_pcdata && c.type() != pugi::node_cdata) continue;
    // Text split by comments or CDATA sections is joined (copied only then).
    if (pieces == 0) first = c.value();
    else if (pieces == 1) *storage = std::string(first) + c.value();
    else *storage += c.value();
    ++pieces;
  }
  return pieces > 1 ? std::string_view(*storage) : first;
}

// A token as from_chars reads it (a double through read_decimal: libc++'s
// from_chars reads no floating point).
static std::from_chars_result read_number(const char* first, const char* last, double& v) {
  return read_decimal(first, last, v);
}
static std::from_chars_result read_number(const char* first, const char* last, uint64_t& v) {
  return std::from_chars(first, last, v);
}

// Every token of e's text read by from_chars as a T, with '+' allowed; fails
// naming the token when it is not a `kind` or `in_range` refuses it.
template <class T, class InRange>
std::vector<T> ColladaDocument::parse_all(XmlNode e, const char* kind, InRange in_range, const char* range) const {
  std::string storage;
  std::vector<T> out;
  for_each_token(text(e, &storage), [&](std::string_view token, size_t index) {
    std::string_view t = without_plus(token);
    T v{};
    auto [end, ec] = read_number(t.data(), t.data() + t.size(), v);
    if (ec == std::errc::invalid_argument || end != t.data() + t.size())
      fail(e, ordinal(index) + " (\"" + quoted(token) + "\") is not " + kind);
    if (ec == std::errc::result_out_of_range || !in_range(v))
      fail(e, ordinal(index) + " (\"" + quoted(token) + "\") is not " + range);
    out.push_back(v);
  });
  return out;
}

std::vector<double> ColladaDocument::numbers(XmlNode e) const {
  return parse_all<double>(
      e, "a number", [](double v) { return std::isfinite(v) && std::abs(v) <= kMaxMagnitude; },
      "a finite number of at most 1e30 in magnitude");
}

std::vector<double> ColladaDocument::numbers(XmlNode e, size_t n) const {
  std::vector<double> v = numbers(e);
  if (v.size() != n) fail(e, "expected " + std::to_string(n) + " numbers, got " + std::to_string(v.size()));
  return v;
}

Vec3 ColladaDocument::vec3(XmlNode e) const {
  std::vector<double> v = numbers(e, 3);
  return Vec3(v[0], v[1], v[2]);
}

Spectrum ColladaDocument::color(XmlNode e) const {
  std::vector<double> v = numbers(e);
  if (v.size() != 3 && v.size() != 4)
    fail(e, "expected a colour of 3 numbers (r g b) or 4 (r g b a), got " + std::to_string(v.size()) + " numbers");
  for (int i = 0; i < 3; ++i)
    if (v[i] < 0.0) fail(e, "colour components must not be negative, got " + format_number(v[i]));
  return Spectrum(v[0], v[1], v[2]);
}

std::vector<uint32_t> ColladaDocument::integers(XmlNode e) const {
  std::vector<uint64_t> v = parse_all<uint64_t>(
      e, "a non-negative integer", [](uint64_t i) { return i <= UINT32_MAX; }, "at most 4294967295");
  return std::vector<uint32_t>(v.begin(), v.end());
}

uint64_t ColladaDocument::integer_attribute(XmlNode e, const char* name) const {
  if (!e.attribute(name)) fail(e, std::string("missing attribute ") + name);
  return integer_attribute(e, name, 0);
}

uint64_t ColladaDocument::integer_attribute(XmlNode e, const char* name, uint64_t fallback) const {
  pugi::xml_attribute a = e.attribute(name);
  if (!a) return fallback;
  std::string_view t = without_plus(a.value());
  uint64_t v = 0;
  auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size() || v > UINT32_MAX)
    fail(e, std::string(name) + "=\"" + quoted(a.value()) + "\": expected an integer in [0, 4294967295]");
  return v;
}

}  // namespace pt
