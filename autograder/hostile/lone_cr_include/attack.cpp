// Hostile: a lone carriage return ends a line for GCC but not for a scanner
// that splits lines at LF: the #include after `pt_marker`, behind a CR on the
// same LF line, is a directive to the compiler only (27.5/27.5 from the
// stubs on main before the process boundary).
static int pt_marker = 0;#include <gtest/gtest.h>
// The same listener as bom_hidden_include's, which clears each test's result
// once it ends, starts here:
namespace {
testing::UnitTest* const pt_registry = testing::UnitTest::GetInstance();
}  // namespace
