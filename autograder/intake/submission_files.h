#pragma once
// Reading a submission (a folder or a .zip) for `pt-grade submission`. Only
// the task files are taken: `partN_<name>.cpp` at the top level or in
// `tasks/` (one enclosing folder, as zipping a folder makes, is looked
// through). Anything else rejects the whole submission with a list of what
// was found, before anything is built; the operating system's metadata
// (__MACOSX/, .DS_Store, Thumbs.db) is skipped with a note. Nothing is ever
// read past the size limit, so a zip bomb or a huge file costs nothing.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace pt::grade {

constexpr size_t kMaxTaskFileBytes = 1 << 20;  // 1 MiB: the stubs are 2 KB, a full solution about 15 KB
constexpr size_t kMaxSubmissionEntries = 200;  // entries looked at before giving up

struct TaskFile {
  int part = 0;
  std::string name;      // e.g. part1_raygen_intersect.cpp
  std::string where;     // as it appeared in the submission, e.g. tasks/part1_raygen_intersect.cpp
  std::string text;      // empty when too_large
  bool too_large = false;
};

struct Submission {
  std::vector<TaskFile> files;        // at most one per part, by part number
  std::vector<std::string> problems;  // non-empty: the submission is rejected, nothing is graded
  std::vector<std::string> notes;     // what was skipped
};

// `expected`: part number -> the task file's name (the kit's tasks/ holds them).
Submission read_submission(const std::string& path, const std::map<int, std::string>& expected);

}  // namespace pt::grade
