#include "build_paths.h"

namespace pt::grade::build_paths {

const char* default_kit() { return PT_DEFAULT_KIT; }
const char* grade_readable() { return PT_GRADE_READABLE; }
const char* source_root() { return PT_SOURCE_ROOT; }
const char* binary_root() { return PT_BINARY_ROOT; }

}  // namespace pt::grade::build_paths
