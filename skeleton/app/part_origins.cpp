#include "app/part_origins.h"

#include <cctype>

namespace pt {

std::string part_origins(const std::string& student_parts, const std::string& chosen_by) {
  std::string yours, solution;
  for (char n = '1'; n <= '5'; ++n) {
    std::string& list = student_parts.find(n) != std::string::npos ? yours : solution;
    list += std::string(list.empty() ? "" : ", ") + n;
  }
  std::string why;
  if (!solution.empty() && !yours.empty() && chosen_by == "PT_REFERENCE_PARTS") why = " (PT_REFERENCE_PARTS)";
  if (!solution.empty() && chosen_by == "auto")
    why = " (a part is yours once no task of its file throws NotImplemented; -DPT_REFERENCE_PARTS chooses "
          "otherwise: README)";
  return "parts from tasks/ (yours): " + (yours.empty() ? std::string("none") : yours) +
         "; from the course's solution: " + (solution.empty() ? std::string("none") : solution) + why;
}

std::string stub_hint(const std::string& message) {
  const size_t at = message.find("not implemented: P");
  if (at == std::string::npos || at + 18 >= message.size() || !std::isdigit((unsigned char)message[at + 18]))
    return "";
  const std::string part(1, message[at + 18]);
  return "part " + part + " is not done in tasks/: to render with the course's solution of part " + part +
         " meanwhile,\n  cmake --preset default -DPT_REFERENCE_PARTS=\"" + part +
         "\" (a list: \"2;3\"), then build again; -DPT_REFERENCE_PARTS=auto (the default) takes each part "
         "from the solution while its task file still throws NotImplemented";
}

}  // namespace pt
