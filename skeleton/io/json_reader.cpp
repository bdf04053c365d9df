#include "io/json_reader.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "io/input_file.h"
#include "io/scene_loader.h"

namespace pt {

namespace {

// Builds the document from SAX events. nlohmann's own DOM parser would do,
// but only the SAX interface reports where a too-large number is (the DOM
// parser throws out_of_range without a position) and lets us refuse duplicate
// keys instead of silently keeping the last one.
class DomBuilder : public nlohmann::json_sax<json> {
 public:
  json root;
  // Set when parsing stopped: a syntax error (with its byte offset) or a
  // duplicate key (with its pointer).
  std::optional<size_t> error_offset;
  std::string error_message, error_token, duplicate_key;

  bool null() override { return put(nullptr); }
  bool boolean(bool v) override { return put(v); }
  bool number_integer(number_integer_t v) override { return put(v); }
  bool number_unsigned(number_unsigned_t v) override { return put(v); }
  bool number_float(number_float_t v, const string_t&) override { return put(v); }
  bool string(string_t& v) override { return put(std::move(v)); }
  bool binary(binary_t& v) override { return put(json::binary(std::move(v))); }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& k) override {
    Frame& f = stack_.back();
    if (f.value->contains(k)) {
      duplicate_key = child(pointer(), k);
      return false;
    }
    f.key = k;
    return true;
  }

  bool parse_error(std::size_t offset, const std::string& token, const json::exception& ex) override {
    error_offset = offset;
    error_token = token;
    error_message = ex.what();
    is_overflow_ = dynamic_cast<const json::out_of_range*>(&ex) != nullptr;
    return false;
  }

  // Byte offset of the start of what went wrong. For syntax errors nlohmann
  // counts the offending character as read; a too-large number is reported
  // after its last digit, so step back over the number.
  size_t error_start() const {
    size_t end = *error_offset;
    if (is_overflow_) return end >= error_token.size() ? end - error_token.size() : 0;
    return end > 0 ? end - 1 : 0;
  }

 private:
  struct Frame {
    json* value;
    std::string name;  // how the parent refers to it (pointer segment)
    std::string key;   // the key whose value comes next, for objects
  };
  std::vector<Frame> stack_;
  bool is_overflow_ = false;

  std::string pointer() const {
    std::string p;
    for (size_t i = 1; i < stack_.size(); ++i) p += "/" + stack_[i].name;
    return p;
  }

  // Stores a value where the document expects the next one; returns it.
  json* insert(json&& v, std::string* name) {
    if (stack_.empty()) {
      root = std::move(v);
      return &root;
    }
    Frame& f = stack_.back();
    if (f.value->is_array()) {
      *name = std::to_string(f.value->size());
      f.value->push_back(std::move(v));
      return &f.value->back();
    }
    *name = child("", f.key).substr(1);
    return &((*f.value)[f.key] = std::move(v));
  }
  bool put(json&& v) {
    std::string name;
    insert(std::move(v), &name);
    return true;
  }
  // Containers stay on the stack while their elements arrive. Pointers into
  // the tree stay valid: only the innermost open container is ever appended to.
  bool open(json&& v) {
    std::string name;
    json* p = insert(std::move(v), &name);
    stack_.push_back({p, name, {}});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }
};

// "[json.exception.parse_error.101] parse error at line 1, column 2: syntax
// error ..." -> "syntax error ...": the place is given in our own format.
std::string strip_nlohmann_prefix(std::string m) {
  if (!m.empty() && m[0] == '[') {
    size_t end = m.find("] ");
    if (end != std::string::npos) m = m.substr(end + 2);
  }
  if (m.rfind("parse error", 0) == 0) {
    size_t colon = m.find(": ");
    if (colon != std::string::npos) m = m.substr(colon + 2);
  }
  return m;
}

const char* with_article(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    default: return "a number";
  }
}

const char* describe(Range r) {
  switch (r) {
    case Range::NonNegative: return "a non-negative number";
    case Range::Positive: return "a positive number";
    case Range::Unit: return "a number in [0, 1]";
    default: return "a finite number";
  }
}

bool in_range(double v, Range r) {
  if (!std::isfinite(v) || std::abs(v) > kMaxMagnitude) return false;
  switch (r) {
    case Range::NonNegative: return v >= 0.0;
    case Range::Positive: return v > 0.0;
    case Range::Unit: return v >= 0.0 && v <= 1.0;
    default: return true;
  }
}

}  // namespace

json parse_json_file(const std::string& path, const char* what) {
  const std::string text = read_input_file(path, kMaxSceneFileBytes, what);
  // nlohmann stops at a NUL byte as if the text ended there, so that whatever
  // follows (the rest of the scene, or garbage) would be silently ignored.
  if (size_t nul = text.find('\0'); nul != std::string::npos) {
    TextPosition at = text_position(text, nul);
    throw SceneError(path + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                     ": a NUL byte (JSON is text; is this a binary or damaged file?)");
  }

  DomBuilder dom;
  if (json::sax_parse(text, &dom)) return std::move(dom.root);
  if (!dom.duplicate_key.empty()) throw SceneError(path + ": " + dom.duplicate_key + ": duplicate key");
  TextPosition at = text_position(text, dom.error_offset ? dom.error_start() : text.size());
  throw SceneError(path + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
                   strip_nlohmann_prefix(dom.error_message));
}

std::string child(const std::string& pointer, const std::string& key) {
  std::string escaped;
  for (char c : key) {
    if (c == '~') escaped += "~0";
    else if (c == '/') escaped += "~1";
    else escaped += c;
  }
  return pointer + "/" + escaped;
}

std::string child(const std::string& pointer, size_t index) { return pointer + "/" + std::to_string(index); }

void JsonReader::fail(const std::string& pointer, const std::string& message) const {
  throw SceneError(file_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + message);
}

void JsonReader::expect_object(const json& j, const std::string& pointer,
                               std::initializer_list<const char*> allowed) const {
  if (!j.is_object()) fail(pointer, std::string("expected an object, got ") + with_article(j));
  for (const auto& item : j.items()) {
    bool known = false;
    for (const char* a : allowed) known = known || item.key() == a;
    if (known) continue;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail(child(pointer, item.key()), "unknown key \"" + item.key() + "\" (allowed here: " + list + ")");
  }
}

void JsonReader::expect_array(const json& j, const std::string& pointer) const {
  if (!j.is_array()) fail(pointer, std::string("expected an array, got ") + with_article(j));
}

const json& JsonReader::required(const json& obj, const std::string& pointer, const char* key) const {
  auto it = obj.find(key);
  if (it == obj.end()) fail(pointer, std::string("missing required field \"") + key + "\"");
  return *it;
}

double JsonReader::number(const json& j, const std::string& pointer, Range range) const {
  if (!j.is_number()) fail(pointer, std::string("expected ") + describe(range) + ", got " + with_article(j));
  double v = j.get<double>();
  if (!in_range(v, range)) {
    std::string why = std::isfinite(v) && std::abs(v) > kMaxMagnitude ? " (at most 1e30 in magnitude)" : "";
    fail(pointer, std::string("expected ") + describe(range) + why + ", got " + format_number(v));
  }
  return v;
}

Vec3 JsonReader::vec3(const json& j, const std::string& pointer, Range range) const {
  if (!j.is_array()) fail(pointer, std::string("expected an array of 3 numbers, got ") + with_article(j));
  if (j.size() != 3)
    fail(pointer, "expected an array of 3 numbers, got " + std::to_string(j.size()) + " element" +
                      (j.size() == 1 ? "" : "s"));
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = number(j[i], child(pointer, size_t(i)), range);
  return v;
}

Vec3 JsonReader::nonzero_vec3(const json& j, const std::string& pointer) const {
  Vec3 v = vec3(j, pointer, Range::Any);
  if (glm::length(v) == 0.0) fail(pointer, "expected a non-zero vector");
  return v;
}

std::string JsonReader::string(const json& j, const std::string& pointer) const {
  if (!j.is_string()) fail(pointer, std::string("expected a string, got ") + with_article(j));
  std::string s = j.get<std::string>();
  // "\u0000" is valid JSON, but a file name would end at it when opened.
  if (s.find('\0') != std::string::npos) fail(pointer, "a string may not contain the NUL character (\\u0000)");
  return s;
}

double JsonReader::number_or(const json& obj, const std::string& pointer, const char* key, double fallback,
                             Range range) const {
  auto it = obj.find(key);
  return it == obj.end() ? fallback : number(*it, child(pointer, key), range);
}

Vec3 JsonReader::vec3_or(const json& obj, const std::string& pointer, const char* key, const Vec3& fallback,
                         Range range) const {
  auto it = obj.find(key);
  return it == obj.end() ? fallback : vec3(*it, child(pointer, key), range);
}

}  // namespace pt
