#include "io/decimal_text.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace pt {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// p with `word` (lower case) next, in any case, skipped; else null.
const char* skip_word(const char* p, const char* last, const char* word) {
  for (; *word; ++word, ++p)
    if (p == last || lower(*p) != *word) return nullptr;
  return p;
}

// The end of the from_chars number that starts at p (after its sign), or p.
const char* number_end(const char* p, const char* last) {
  if (const char* q = skip_word(p, last, "inf")) {
    const char* longer = skip_word(q, last, "inity");
    return longer ? longer : q;
  }
  if (const char* q = skip_word(p, last, "nan")) {
    if (q == last || *q != '(') return q;
    const char* r = q + 1;  // nan(n-char-sequence): letters, digits, '_'
    while (r != last && (is_digit(*r) || *r == '_' || (lower(*r) >= 'a' && lower(*r) <= 'z'))) ++r;
    return r != last && *r == ')' ? r + 1 : q;
  }
  const char* q = p;
  while (q != last && is_digit(*q)) ++q;
  bool digits = q != p;
  if (q != last && *q == '.') {
    const char* fraction = ++q;
    while (q != last && is_digit(*q)) ++q;
    digits = digits || q != fraction;
  }
  if (!digits) return p;
  if (q != last && lower(*q) == 'e') {  // an exponent only with its digits
    const char* e = q + 1;
    if (e != last && (*e == '+' || *e == '-')) ++e;
    const char* exponent = e;
    while (e != last && is_digit(*e)) ++e;
    if (e != exponent) q = e;
  }
  return q;
}

}  // namespace

std::from_chars_result read_decimal(const char* first, const char* last, double& value) {
  const char* start = first != last && *first == '-' ? first + 1 : first;
  const char* end = number_end(start, last);
  if (end == start) return {first, std::errc::invalid_argument};
  const std::string text(first, end);  // strtod needs a terminated string
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  // strtod reports ERANGE for a subnormal result too, which from_chars reads
  // as a value: out of range only when nothing of it is left (0) or too much (inf).
  if (errno == ERANGE && (v == 0.0 || std::isinf(v))) return {end, std::errc::result_out_of_range};
  value = v;
  return {end, std::errc()};
}

}  // namespace pt
