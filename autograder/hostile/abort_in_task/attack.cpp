// Hostile (or just broken): abort() in one task, as a failed assert() would.
// Only the tests of P1T4 may lose points.
#include <cstdlib>
