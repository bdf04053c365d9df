// Hostile: compile errors as large as a build can print. Each level of Grow
// doubles the type's name, so the compiler prints a std::pair nested 2^14
// times (about 250 KB) when it says the conversion is impossible; the padding
// (expect.json) adds lines the compiler quotes whole, 250 control characters
// each (6 bytes each in JSON). The build's message was copied into every
// test of the part: 40 lines of 300 bytes, 72 KB of JSON per test.
#include <utility>

template <int N, class T>
struct Grow {
  using type = typename Grow<N - 1, std::pair<T, T>>::type;
};
template <class T>
struct Grow<0, T> {
  using type = T;
};

Grow<14, int>::type huge_type_value = 0;
