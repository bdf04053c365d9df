#pragma once
// What every scene reader (JSON, COLLADA) says about the text of its files:
// where an offset is, how a number is shown, how large numbers may be.
#include <cstddef>
#include <string>

namespace pt {

// Line and column (1-based, in bytes) of a byte offset into `text`.
struct TextPosition {
  size_t line, column;
};
TextPosition text_position(const std::string& text, size_t offset);

// Every number a scene gives must be finite and at most this in magnitude, so
// that no product of a few of them overflows.
constexpr double kMaxMagnitude = 1e30;

// A number as a person would write it in the file ("200", "0.25", "1e+40").
std::string format_number(double v);

}  // namespace pt
