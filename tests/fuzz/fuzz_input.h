#pragma once
// What every fuzz target does: store the fuzzer's bytes as a file and hand
// its path to a loader, exactly as the command line would. Loaders take paths
// (and resolve paths inside a scene relative to it), so the fuzzer exercises
// the whole way in: the size bound, the reading, the format dispatch.
//
// The contract under test: a loader either returns or throws SceneError.
// Anything else (another exception, a crash, a sanitizer report, a hang)
// escapes this function and is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

namespace pt::fuzz {

// Writes data to `file_name` in a directory private to this process (under
// $TMPDIR; /dev/shm is fastest) and calls load(path). The directory also
// holds "mesh.obj", a one-triangle OBJ, so that scene inputs can reach the
// mesh loader. Returns 0 (what LLVMFuzzerTestOneInput returns).
int load_as_file(const uint8_t* data, size_t size, const char* file_name, void (*load)(const std::string& path));

// Whether the last load_as_file ended in a SceneError (for the replayer,
// which checks that every stored crasher is still refused).
bool last_input_refused();

}  // namespace pt::fuzz
