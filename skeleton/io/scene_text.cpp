#include "io/scene_text.h"

#include <algorithm>
#include <sstream>

namespace pt {

TextPosition text_position(const std::string& text, size_t offset) {
  offset = std::min(offset, text.size());
  TextPosition p{1, 1};
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') ++p.line, p.column = 1;
    else ++p.column;
  }
  return p;
}

std::string format_number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace pt
