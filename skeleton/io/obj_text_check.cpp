#include "io/obj_text_check.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <charconv>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "io/decimal_text.h"
#include "io/json_reader.h"  // kMaxMagnitude, the scene format's bound on numbers
#include "io/scene_loader.h"

namespace pt {

namespace {

// The decimal numbers tinyobjloader reads in full: [+-] digits [. digits]
// [e [+-] digits], or with the digits before the point left out. Anything
// else ("nan", "inf", "0x1p3", "1x") it would read as a prefix or as 0.
// Exponents stay within +-300: tinyobjloader's own conversion overflows an
// int past 9 digits and computes 5^exponent (0e999 would come out as NaN).
constexpr int kMaxExponent = 300;
// *exponent_too_large is set for any text that starts like such a number,
// whatever follows (tinyobjloader converts the prefix).
bool is_decimal(std::string_view s, bool* exponent_too_large) {
  *exponent_too_large = false;
  size_t i = 0, digits = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  for (; i < s.size() && std::isdigit((unsigned char)s[i]); ++i) ++digits;
  if (i < s.size() && s[i] == '.')
    for (++i; i < s.size() && std::isdigit((unsigned char)s[i]); ++i) ++digits;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t exp_digits = 0;
    long exponent = 0;
    for (; i < s.size() && std::isdigit((unsigned char)s[i]); ++i, ++exp_digits)
      exponent = std::min(10L * exponent + (s[i] - '0'), long(kMaxExponent) + 1);
    if (exp_digits == 0) return false;
    *exponent_too_large = exponent > kMaxExponent;
  }
  return digits > 0 && i == s.size();
}

// One kind of element that faces index (positions, texture coordinates,
// normals): how many the file has so far, and positive indices that point
// past them (legal if the element comes later in the file).
struct Elements {
  explicit Elements(const char* name) : name(name) {}
  const char* name;
  long long count = 0;
  struct Ref {
    size_t line;
    long long index;
  };
  std::vector<Ref> forward;
};

class ObjChecker {
 public:
  ObjChecker(const std::string& path) : path_(path) {}

  void check(std::string_view text) {
    if (size_t nul = text.find('\0'); nul != std::string_view::npos) {
      line_ = 1;
      for (size_t i = 0; i < nul; ++i)
        if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) ++line_;
      fail("a NUL byte (OBJ is text; is this a binary or damaged file?)");
    }
    // Lines end at \n, \r\n or \r, as tinyobjloader reads them.
    for (size_t start = 0; start < text.size();) {
      size_t end = text.find_first_of("\r\n", start);
      if (end == std::string_view::npos) end = text.size();
      ++line_;
      check_line(text.substr(start, end - start));
      start = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
    }
    for (const Elements* e : {&positions_, &texcoords_, &normals_})
      for (const auto& ref : e->forward)
        if (ref.index > e->count) {
          line_ = ref.line;
          fail("a face refers to " + std::string(e->name) + " " + std::to_string(ref.index) + ", but the file has " +
               std::to_string(e->count));
        }
  }

 private:
  const std::string& path_;
  size_t line_ = 0;
  std::vector<std::string_view> tokens_;
  Elements positions_{"vertex"}, texcoords_{"texture coordinate"}, normals_{"normal"};

  [[noreturn]] void fail(const std::string& message) const {
    throw SceneError(path_ + ":" + std::to_string(line_) + ": " + message);
  }

  void check_line(std::string_view line) {
    std::vector<std::string_view>& tokens = tokens_;  // reused: no allocation per line
    tokens.clear();
    for (size_t i = 0; i < line.size();) {
      if (line[i] == ' ' || line[i] == '\t') {
        ++i;
        continue;
      }
      size_t end = line.find_first_of(" \t", i);
      if (end == std::string_view::npos) end = line.size();
      tokens.push_back(line.substr(i, end - i));
      i = end;
    }
    // A comment only at the start of a line: tinyobjloader reads on past a
    // '#' elsewhere.
    if (tokens.empty() || tokens[0][0] == '#') return;
    const std::string_view key = tokens[0];
    // Every number tinyobjloader converts, even those the framework ignores
    // (texture coordinates, skin weights, tags): an exponent too long
    // overflows its int, which is undefined behaviour.
    if (key == "v" || key == "vn" || key == "vt" || key == "vw" || key == "t")
      for (size_t k = 1; k < tokens.size(); ++k) {
        bool exponent_too_large;
        is_decimal(tokens[k], &exponent_too_large);
        if (exponent_too_large)
          fail("value " + std::string(tokens[k]) + " has an exponent beyond +-" + std::to_string(kMaxExponent));
      }
    if (key == "v") {
      check_xyz(tokens, "vertex");
      ++positions_.count;
    } else if (key == "vn") {
      check_xyz(tokens, "normal");
      ++normals_.count;
    } else if (key == "vt") {
      ++texcoords_.count;
    } else if (key == "vw") {
      // `vw vertex joint weight joint weight ...`: tinyobjloader reads each
      // joint as a float (from a numeric prefix of the token, which strtod
      // reads at least) and converts it to an int; 2^24 keeps that exact.
      for (size_t k = 2; k < tokens.size(); k += 2) {
        double joint = std::strtod(std::string(tokens[k]).c_str(), nullptr);
        if (!(joint >= 0.0 && joint <= double(1 << 24)))
          fail("skin weight joint " + std::string(tokens[k]) + " is not a number in [0, 2^24]");
      }
    } else if (key == "f") {
      if (tokens.size() - 1 > size_t(kMaxFaceVertices))
        fail("a face of " + std::to_string(tokens.size() - 1) + " vertices, more than the " +
             std::to_string(kMaxFaceVertices) + " allowed (triangulation time grows as the square)");
      for (size_t k = 1; k < tokens.size(); ++k) check_corner(tokens[k]);
    } else if (key == "l" || key == "p") {
      // Ignored by the framework, but tinyobjloader reads their indices too.
      for (size_t k = 1; k < tokens.size(); ++k) check_corner(tokens[k]);
    }
  }

  // The x y z of a `v` or `vn`. What follows them (a vertex colour, or a
  // comment) the framework does not use.
  void check_xyz(const std::vector<std::string_view>& tokens, const char* what) {
    if (tokens.size() < 4)
      fail(std::string(what) + " needs 3 numbers (x y z), got " + std::to_string(tokens.size() - 1));
    for (size_t k = 1; k <= 3; ++k) {
      const std::string_view s = tokens[k];
      bool exponent_too_large;
      if (!is_decimal(s, &exponent_too_large))
        fail(std::string(what) + " value \"" + std::string(s) + "\" is not a decimal number");
      // A decimal number: read_decimal reads all of it (but for a leading '+').
      double v = 0.0;
      const size_t sign = s[0] == '+' ? 1 : 0;
      auto [end, ec] = read_decimal(s.data() + sign, s.data() + s.size(), v);
      if (ec != std::errc() || !std::isfinite(v) || std::abs(v) > kMaxMagnitude)
        fail(std::string(what) + " value " + std::string(s) + " is larger than 1e30 in magnitude");
    }
  }

  // v, v/vt, v//vn or v/vt/vn.
  void check_corner(std::string_view corner) {
    std::vector<std::string_view> parts;
    for (size_t start = 0;;) {
      size_t slash = corner.find('/', start);
      parts.push_back(corner.substr(start, slash == std::string_view::npos ? slash : slash - start));
      if (slash == std::string_view::npos) break;
      if (parts.size() == 3) fail("face corner \"" + std::string(corner) + "\" has more than 3 indices");
      start = slash + 1;
    }
    // Only the texture coordinate of v//vn may be left out.
    for (size_t k = 0; k < parts.size(); ++k)
      if (parts[k].empty() && !(k == 1 && parts.size() == 3))
        fail("face corner \"" + std::string(corner) + "\" is not v, v/vt, v//vn or v/vt/vn");
    check_index(parts[0], positions_, corner);
    if (parts.size() >= 2 && !parts[1].empty()) check_index(parts[1], texcoords_, corner);
    if (parts.size() == 3) check_index(parts[2], normals_, corner);
  }

  void check_index(std::string_view s, Elements& e, std::string_view corner) {
    auto bad = [&](const std::string& value, const std::string& why) {
      fail(std::string(e.name) + " index " + value + " in face corner \"" + std::string(corner) + "\"" + why);
    };
    const size_t sign = s[0] == '+' ? 1 : 0;  // from_chars takes '-' only
    long long index = 0;
    auto [end, ec] = std::from_chars(s.data() + sign, s.data() + s.size(), index);
    if (end != s.data() + s.size() || (ec != std::errc() && ec != std::errc::result_out_of_range) ||
        (sign && s.size() > 1 && s[1] == '-'))
      bad("\"" + std::string(s) + "\"", " is not an integer");
    // tinyobjloader reads indices with atoi: beyond an int they would wrap.
    if (ec == std::errc::result_out_of_range || index > INT_MAX || index < -INT_MAX)
      bad(std::string(s), " is out of range");
    if (index == 0) bad("0", " (OBJ counts from 1)");
    if (index < 0 && -index > e.count)
      bad(std::to_string(index),
          std::string(" reaches before the first ") + e.name + " (the file has " + std::to_string(e.count) + " so far)");
    if (index > e.count) e.forward.push_back({line_, index});
  }
};

}  // namespace

void check_obj_text(const std::string& text, const std::string& path) { ObjChecker(path).check(text); }

}  // namespace pt
