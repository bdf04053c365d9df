// io/decimal_text.h reads a double as std::from_chars does (libc++ has no
// floating-point from_chars before LLVM 17, so the framework reads with its
// own scanner and strtod). Where the standard library has one (GCC's), every
// token below must give from_chars's end, error and value exactly.
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

#include "io/decimal_text.h"

namespace pt {
namespace {

const char* const kTokens[] = {
    "0", "-0", "1", "12.5", "-3.25e2", ".5", "5.", "-.5e-1", "1e", "1e+", "1e-", "1e5x", "1.2.3", "+1", " 1", "",
    "-", ".", "e5", "0x1p3", "0x", "inf", "-INF", "Infinity", "infinit", "nan", "NaN(abc_1)", "nan(", "nan()x",
    "1e400", "-1e400", "1e-400", "4.9e-324", "2.2250738585072014e-308", "0.1", "123456789012345678901234567890",
    "9007199254740993", "1.7976931348623157e308", "12abc", "-x", "1_000"};

#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
TEST(DecimalText, ReadsEveryTokenAsFromChars) {
  for (const char* token : kTokens) {
    const char* end = token + std::strlen(token);
    double ours = -7.0, theirs = -7.0;
    const auto a = read_decimal(token, end, ours);
    const auto b = std::from_chars(token, end, theirs);
    EXPECT_EQ(a.ptr - token, b.ptr - token) << "\"" << token << "\"";
    EXPECT_EQ(a.ec, b.ec) << "\"" << token << "\"";
    if (b.ec == std::errc()) {
      if (std::isnan(theirs))
        EXPECT_TRUE(std::isnan(ours)) << "\"" << token << "\"";
      else
        EXPECT_EQ(ours, theirs) << "\"" << token << "\"";  // exactly: both round correctly
    }
  }
}
#endif

// What holds on every standard library, from_chars or not.
TEST(DecimalText, ReadsDecimalsAndStopsWhereFromCharsWould) {
  double v = 0;
  const std::string t = "-3.25e2 rest";
  auto r = read_decimal(t.data(), t.data() + t.size(), v);
  EXPECT_EQ(r.ec, std::errc());
  EXPECT_EQ(r.ptr - t.data(), 7);
  EXPECT_EQ(v, -325.0);
  const std::string plus = "+1";
  r = read_decimal(plus.data(), plus.data() + plus.size(), v);
  EXPECT_EQ(r.ec, std::errc::invalid_argument);
  EXPECT_EQ(r.ptr, plus.data());
  const std::string hex = "0x10";
  r = read_decimal(hex.data(), hex.data() + hex.size(), v);
  EXPECT_EQ(r.ptr - hex.data(), 1);  // the 0, as from_chars: no hexadecimal
  EXPECT_EQ(v, 0.0);
  const std::string huge = "1e400";
  v = 5;
  r = read_decimal(huge.data(), huge.data() + huge.size(), v);
  EXPECT_EQ(r.ec, std::errc::result_out_of_range);
  EXPECT_EQ(v, 5.0);  // left as it was
}

}  // namespace
}  // namespace pt
