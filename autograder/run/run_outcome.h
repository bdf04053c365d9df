#pragma once
// A worker's RunOutcome on its way back to the grader (grade_part.cpp): the
// grader's helper process that ran the worker writes it to a pipe as one JSON
// object, and the grader reads it.
//
// Only the helper writes it: the pipe is close-on-exec and the sandbox closes
// every other descriptor before the worker starts, and the worker's processes
// are all dead before the helper writes. Where the worker could still reach
// the pipe (without namespaces and without the user switch, through the
// helper's /proc/PID/fd), it could only write before the helper does: bytes
// in front of the real object make the whole unreadable, never another
// outcome. Anything but exactly one object with exactly these fields, of
// these types, in at most max_bytes, reads as a run that was lost.
#include <cstddef>
#include <string>
#include <string_view>

#include "sandbox/sandbox.h"

namespace pt::grade {

// Far above what a run keeps (SandboxLimits: head and tail of its output,
// each byte at most six when escaped).
inline constexpr size_t kMaxOutcomeBytes = 64u << 20;

// Invalid UTF-8 in the output or error becomes U+FFFD, as in results.json.
std::string outcome_json(const RunOutcome& r);
RunOutcome parse_outcome(std::string_view text);

void write_outcome(int fd, const RunOutcome& r);
RunOutcome read_outcome(int fd, size_t max_bytes = kMaxOutcomeBytes);

}  // namespace pt::grade
