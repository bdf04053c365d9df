#pragma once

namespace pt {

// The `pathtracer` command line (DESIGN section 8). Returns the exit status.
int run_cli(int argc, char** argv);

}  // namespace pt
