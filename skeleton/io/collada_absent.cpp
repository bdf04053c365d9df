// The COLLADA loader's stand-in in a build without pugixml (the XML parser it
// reads with: cmake/dependencies.cmake). JSON scenes load as ever; a .dae says
// what is missing and how to get it, instead of the build failing for a
// format most scenes do not use.
#include "io/collada_loader.h"

namespace pt {

void load_collada(const std::string& path, LoadedScene*, const ColladaLimits&) {
  throw SceneError(path +
                   ": this build reads no COLLADA (.dae) scenes: pugixml was not found when it was configured "
                   "(macOS: brew install pugixml; Debian or Ubuntu: apt install libpugixml-dev; then configure again), "
                   "or use a .json scene");
}

}  // namespace pt
