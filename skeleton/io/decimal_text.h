#pragma once
// A double read from text as std::from_chars reads it (general format: an
// optional '-', digits with an optional point and exponent, or inf / nan; no
// '+', no leading space, no hexadecimal), on every standard library: clang's
// libc++ (macOS's) has no floating-point from_chars before LLVM 17.
#include <charconv>

namespace pt {

// The longest prefix of [first, last) that from_chars would read, converted
// (correctly rounded, by the C library's strtod in the "C" locale). ptr: the
// end of that prefix, or `first` with ec = invalid_argument when there is
// none; ec = result_out_of_range when the value overflows or underflows to 0
// (a subnormal value is read, as from_chars reads it).
std::from_chars_result read_decimal(const char* first, const char* last, double& value);

}  // namespace pt
