#pragma once
// Image files: the linear EXR that numbers are read from, the PNG people look at.
#include <string>

#include "render/image.h"

namespace pt {

// Linear EXR (float RGB). Writers throw std::runtime_error naming the file and
// the system's reason when any write fails (a full disk, a missing directory),
// and then remove a partly written regular file. read_exr throws naming the
// file when it is missing, not an EXR, or larger than the largest image a
// render may make (render/limits.h).
void write_exr(const std::string& path, const Image& image);
Image read_exr(const std::string& path);

// 8-bit sRGB PNG: radiance scaled by 2^exposure, clamped to [0, 1], encoded
// with the sRGB transfer curve. Fails as write_exr does.
void write_png(const std::string& path, const Image& image, double exposure = 0.0);

}  // namespace pt
