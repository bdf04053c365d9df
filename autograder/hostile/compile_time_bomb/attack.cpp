// Hostile: take the grader down while it compiles. Each static_assert makes
// the compiler evaluate three nested loops of 200000 steps, up to its limit of
// 2^25 operations (about 8 s of one core each); 64 of them would keep it busy
// for minutes. The per-part build limit must stop it, and cost nothing but
// this part: the submission's part 5 is the solution, and must get every point.
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
