#pragma once
// Vector types of the framework: GLM in double precision, so that closed-form
// test values (hit distances, barycentrics) can be checked to ~1e-9.
#include <glm/glm.hpp>
#include <limits>
#include <ostream>

namespace pt {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Mat3 = glm::dmat3;
using Mat4 = glm::dmat4;

// Linear RGB radiance (or reflectance). A separate name keeps signatures honest
// about what a value means, even though it is the same type as a direction.
using Spectrum = glm::dvec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kInvPi = 1.0 / kPi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Photometric luminance of linear sRGB primaries (Rec. 709 weights): the scalar
// that adaptive sampling and image statistics look at.
inline double illuminance(const Spectrum& s) { return 0.2126 * s.r + 0.7152 * s.g + 0.0722 * s.b; }

inline bool is_finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline double max_component(const Vec3& v) { return glm::max(v.x, glm::max(v.y, v.z)); }

}  // namespace pt

// Streamable so that test failures can print their inputs: `<< "ray " << r`.
namespace glm {
inline std::ostream& operator<<(std::ostream& os, const dvec3& v) {
  return os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
}
inline std::ostream& operator<<(std::ostream& os, const dvec2& v) {
  return os << "(" << v.x << ", " << v.y << ")";
}
}  // namespace glm
