// Hostile: a compile-time bomb (as in compile_time_bomb), and the grader is
// killed from outside while the compiler works on it, as an outer timeout
// would. Every static_assert keeps the compiler busy for seconds; nothing of
// the build may outlive the grader.
constexpr unsigned long long spin(unsigned long long seed) {
  unsigned long long s = seed;
  for (unsigned long i = 0; i < 200000; ++i)
    for (unsigned long j = 0; j < 200000; ++j)
      for (unsigned long k = 0; k < 200000; ++k) s += i ^ j ^ k;
  return s;
}
#define BOMB(n) static_assert(spin(n) != 1, "");
#define BOMB4(n) BOMB(n) BOMB(n + 1) BOMB(n + 2) BOMB(n + 3)
#define BOMB16(n) BOMB4(n) BOMB4(n + 4) BOMB4(n + 8) BOMB4(n + 12)
BOMB16(0) BOMB16(16) BOMB16(32) BOMB16(48)
