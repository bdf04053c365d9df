#include "support/seed.h"

namespace pt::test {

static uint64_t g_offset = 0;

void set_seed_offset(uint64_t offset) { g_offset = offset; }
uint64_t seed(uint64_t base) { return base + 0x9e3779b97f4a7c15ull * g_offset; }

}  // namespace pt::test
