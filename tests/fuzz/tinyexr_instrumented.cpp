// The fuzz build compiles tinyexr from its header (as tinyobj_instrumented.cpp
// does tinyobjloader), so that the sanitizers and libFuzzer's coverage see
// inside the EXR decoder. zlib decodes ZIP blocks, as in Debian's build.
#define TINYEXR_IMPLEMENTATION
#define TINYEXR_USE_MINIZ 0
#include <zlib.h>
#include <tinyexr.h>
