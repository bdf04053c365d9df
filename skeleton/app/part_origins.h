#pragma once
// Which parts a renderer took from tasks/ and which from the course's
// solution, as the build chose (the top-level CMakeLists: PT_REFERENCE_PARTS,
// "auto" by default: the solution stands in for a part whose task file still
// throws NotImplemented), said at the start of a render and on the viewer's
// page so that nobody mistakes the solution's image for their own.
#include <string>

namespace pt {

// "parts from tasks/ (yours): 1, 2; from the course's solution: 3, 4, 5 (...)".
// `student_parts`: the digits of the parts taken from tasks/ ("1,2"; "" for
// none); `chosen_by`: "auto" or "PT_REFERENCE_PARTS", how the others were.
std::string part_origins(const std::string& student_parts, const std::string& chosen_by);

// For a task's "not implemented: PnTm ..." message, how to let the solution
// stand in for part n meanwhile; "" for any other message.
std::string stub_hint(const std::string& message);

}  // namespace pt
