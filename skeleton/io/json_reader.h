#pragma once
// Reading JSON scene files with errors that say where: syntax errors as
// "file:LINE:COL: message", content errors as "file: /json/pointer: message".
// Internal to the scene loader (nlohmann is a private dependency of the
// skeleton library, so keep this header out of public ones).
#include <initializer_list>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/vec.h"
#include "io/scene_text.h"

namespace pt {

using json = nlohmann::json;

// Parses a whole file of at most kMaxSceneFileBytes; `what` names it in errors
// ("a scene file", "a camera file"). Throws SceneError "path: cannot open: ...",
// "path:L:C: ..." for syntax errors, NUL bytes and numbers too large for a
// double, and "path: /pointer: duplicate key" (nlohmann would silently keep
// the last).
json parse_json_file(const std::string& path, const char* what);

// Which numbers a field accepts. Every number must also be finite and at
// most kMaxMagnitude in size (scene_text.h).
enum class Range { Any, NonNegative, Positive, Unit /* [0, 1] */ };

// Typed, checked access to the values of one parsed file. Every method takes
// the JSON pointer of what it reads, for the error message.
class JsonReader {
 public:
  explicit JsonReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const;

  // Fails unless `j` is an object whose keys are all in `allowed`.
  void expect_object(const json& j, const std::string& pointer, std::initializer_list<const char*> allowed) const;
  void expect_array(const json& j, const std::string& pointer) const;

  // obj[key], failing when absent: "pointer: missing required field "key"".
  const json& required(const json& obj, const std::string& pointer, const char* key) const;

  double number(const json& j, const std::string& pointer, Range range) const;
  Vec3 vec3(const json& j, const std::string& pointer, Range range) const;
  // A vec3 that must not be the zero vector (directions, edges, axes).
  Vec3 nonzero_vec3(const json& j, const std::string& pointer) const;
  std::string string(const json& j, const std::string& pointer) const;

  // Optional fields: the value of obj[key] when present, else the fallback.
  double number_or(const json& obj, const std::string& pointer, const char* key, double fallback, Range range) const;
  Vec3 vec3_or(const json& obj, const std::string& pointer, const char* key, const Vec3& fallback, Range range) const;

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// pointer + "/" + key, escaped as RFC 6901 asks ("~" -> "~0", "/" -> "~1").
std::string child(const std::string& pointer, const std::string& key);
std::string child(const std::string& pointer, size_t index);

}  // namespace pt
