#include "intake/file_directives.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <set>

namespace pt::grade {

namespace {

// The text with line splices undone (a backslash, then spaces as GCC allows,
// then a line end: LF, CRLF or a lone CR), lower case, and the submitted
// line of each character.
struct Flat {
  std::string text;
  std::vector<int> line_of;
};

Flat unspliced(const std::string& src) {
  Flat f;
  int line = 1;
  for (size_t i = 0; i < src.size(); ++i) {
    if (src[i] == '\\') {
      size_t j = i + 1;
      while (j < src.size() && (src[j] == ' ' || src[j] == '\t' || src[j] == '\f' || src[j] == '\v')) ++j;
      if (j < src.size() && (src[j] == '\n' || src[j] == '\r')) {
        i = src[j] == '\r' && j + 1 < src.size() && src[j + 1] == '\n' ? j + 1 : j;
        ++line;
        continue;
      }
    }
    f.text += static_cast<char>(std::tolower(static_cast<unsigned char>(src[i])));
    f.line_of.push_back(line);
    if (src[i] == '\n') ++line;
  }
  return f;
}

// Past white space and comments from i.
size_t past_gap(const std::string& t, size_t i) {
  while (i < t.size()) {
    if (std::isspace(static_cast<unsigned char>(t[i]))) {
      ++i;
    } else if (t.compare(i, 2, "/*") == 0) {
      const size_t end = t.find("*/", i + 2);
      i = end == std::string::npos ? t.size() : end + 2;
    } else if (t.compare(i, 2, "//") == 0) {
      i = std::min(t.size(), t.find('\n', i));
    } else {
      break;
    }
  }
  return i;
}

// Adjacent literals joined: a quote, a gap, an encoding prefix and a quote
// are dropped wherever they are. Inside a literal this can drop more than
// the compiler joins, so the text is searched both as it is and joined.
Flat joined(const Flat& f) {
  Flat out;
  const std::string& t = f.text;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '"') {
      size_t j = past_gap(t, i + 1);
      const size_t prefix = j;  // u8, u, U, L, then R: at most three letters
      while (j < t.size() && j < prefix + 3 && t[j] != '\0' && std::strchr("u8lr", t[j])) ++j;
      if (j < t.size() && t[j] == '"' && j > i + 1) {
        i = j;
        continue;
      }
    }
    out.text += t[i];
    out.line_of.push_back(f.line_of[i]);
  }
  return out;
}

}  // namespace

std::vector<FileDirective> file_directives(const std::string& text) {
  std::vector<FileDirective> found;
  std::set<std::pair<int, int>> said;  // (line, kind)
  auto add = [&](int line, int kind, const std::string& what) {
    if (said.insert({line, kind}).second) found.push_back({line, what});
  };
  const Flat flat = unspliced(text);
  const std::string& t = flat.text;
  // #embed and %:embed, with white space or comments after the # (a
  // directive's # need not start a line for this search).
  for (size_t i = 0; i < t.size(); ++i) {
    const size_t hash = t[i] == '#' ? 1 : t.compare(i, 2, "%:") == 0 ? 2 : 0;
    const size_t name = hash ? past_gap(t, i + hash) : 0;
    if (hash && t.compare(name, 5, "embed") == 0 &&
        (name + 5 == t.size() || !(std::isalnum(static_cast<unsigned char>(t[name + 5])) || t[name + 5] == '_')))
      add(flat.line_of[i], 0, "#embed reads a file into the program as data: a task file may not");
  }
  const Flat strings = joined(flat);
  for (const Flat* f : {&flat, &strings})
    for (const char* directive : {"incbin", ".include"})
      for (size_t at = f->text.find(directive); at != std::string::npos; at = f->text.find(directive, at + 1))
        add(f->line_of[at], 1, "the assembler directive .incbin or .include reads a file at compile time");
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
  return found;
}

}  // namespace pt::grade
