#pragma once
// Replacing a file so that a reader (or a grader killed half-way) sees the old
// contents or the new, never a mix: a temporary file in the same folder,
// flushed to disk, then renamed over the target.
#include <string>

namespace pt::grade {

// Throws std::runtime_error naming the file when it cannot be written.
void write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace pt::grade
