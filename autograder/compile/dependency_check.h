#pragma once
// The compiler's own view of what a task file read (pt-grade submission and
// check-submission, after each part's build): ninja's record of each
// object's dependency output, checked against the files a task file may read.
#include <string>
#include <vector>

namespace pt::grade {

// The files the compiler opened for objects whose path holds object_marker
// (ninja's dependency record in build_dir) that lie in none of the `allowed`
// folders and, with a probe_marker, that the probe object (the kit's
// pt_header_probe: every allowed standard header and GLM) did not open
// either; a missing probe record is itself reported.
std::vector<std::string> unexpected_dependencies(const std::string& build_dir, const std::string& object_marker,
                                                 const std::vector<std::string>& allowed,
                                                 const std::string& probe_marker = "");

}  // namespace pt::grade
