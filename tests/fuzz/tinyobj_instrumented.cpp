// The fuzz build compiles tinyobjloader from its header, so that the sanitizers
// and libFuzzer's coverage see inside it; the normal build links Debian's
// shared library. The executable's definitions take precedence over the
// library's (ELF symbol interposition), and both come from the same package.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
