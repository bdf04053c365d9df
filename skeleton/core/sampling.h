#pragma once
// Warps from the unit square to directions, each paired with its pdf (per unit
// solid angle) so that tests can check one against the other.
#include "core/vec.h"

namespace pt {

Vec3 sample_uniform_hemisphere(const Vec2& u);  // z >= 0
double pdf_uniform_hemisphere(const Vec3& w);   // 1/(2 pi) for z >= 0

Vec3 sample_cosine_hemisphere(const Vec2& u);  // Malley's method: disk then lift
double pdf_cosine_hemisphere(const Vec3& w);   // cos(theta)/pi for z >= 0

Vec3 sample_uniform_sphere(const Vec2& u);
double pdf_uniform_sphere(const Vec3& w);  // 1/(4 pi)

Vec2 sample_concentric_disk(const Vec2& u);  // Shirley-Chiu: area preserving, low distortion

}  // namespace pt
