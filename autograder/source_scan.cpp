#include "source_scan.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <cstring>

namespace pt::grade {

// The C++17 standard library's headers, and the C headers it keeps.
const std::set<std::string>& standard_headers() {
  static const std::set<std::string> names = {
      "algorithm", "any", "array", "atomic", "bitset", "cassert", "ccomplex", "cctype", "cerrno", "cfenv",
      "cfloat", "charconv", "chrono", "cinttypes", "ciso646", "climits", "clocale", "cmath", "codecvt", "complex",
      "condition_variable", "csetjmp", "csignal", "cstdalign", "cstdarg", "cstdbool", "cstddef", "cstdint",
      "cstdio", "cstdlib", "cstring", "ctgmath", "ctime", "cuchar", "cwchar", "cwctype", "deque", "exception",
      "execution", "filesystem", "forward_list", "fstream", "functional", "future", "initializer_list", "iomanip",
      "ios", "iosfwd", "iostream", "istream", "iterator", "limits", "list", "locale", "map", "memory",
      "memory_resource", "mutex", "new", "numeric", "optional", "ostream", "queue", "random", "ratio", "regex",
      "scoped_allocator", "set", "shared_mutex", "sstream", "stack", "stdexcept", "streambuf", "string",
      "string_view", "strstream", "system_error", "thread", "tuple", "type_traits", "typeindex", "typeinfo",
      "unordered_map", "unordered_set", "utility", "valarray", "variant", "vector",
      // C headers kept by C++ ([depr.c.headers])
      "assert.h", "complex.h", "ctype.h", "errno.h", "fenv.h", "float.h", "inttypes.h", "iso646.h", "limits.h",
      "locale.h", "math.h", "setjmp.h", "signal.h", "stdalign.h", "stdarg.h", "stdbool.h", "stddef.h", "stdint.h",
      "stdio.h", "stdlib.h", "string.h", "tgmath.h", "time.h", "uchar.h", "wchar.h", "wctype.h"};
  return names;
}

namespace {

// GLM is the framework's vector library (core/vec.h includes it): its headers
// are as harmless as the standard library's, and students use them.
bool is_glm_header(const std::string& name) {
  if (name.rfind("glm/", 0) != 0 || name.find("..") != std::string::npos) return false;
  return std::all_of(name.begin(), name.end(),
                     [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '/' || c == '.'; });
}

// The text after the preprocessor's phases 2 and 3 as far as directives and
// identifiers need them: line splices removed, each comment replaced by one
// space, literals kept. line_of[i] is the submitted line of text[i].
struct Cleaned {
  std::string text;
  std::vector<int> line_of;
  std::vector<bool> literal;                          // text[i] is inside a string or character literal
  struct Literal {
    int line;
    std::string text;   // as written, quotes included
    size_t begin, end;  // where it is in `text` above
  };
  std::vector<Literal> strings;  // string literals
};

bool ident_char(char c) { return std::isalnum((unsigned char)c) || c == '_'; }

// The ways a file can be read differently by this scanner and the compiler,
// refused before anything else is read: GCC skips a UTF-8 byte-order mark and
// ends a line at a lone CR, so `\xEF\xBB\xBF#include <...>` or `x;\r#include
// <...>` would be directives the scanner could not see as such. Each finding
// names the first line it happens on.
std::vector<SourceFinding> encoding_problems(const std::string& src) {
  std::vector<SourceFinding> found;
  std::set<std::string> said;
  auto add = [&](int line, const std::string& what) {
    if (said.insert(what).second) found.push_back({line, what});
  };
  if (src.rfind("\xEF\xBB\xBF", 0) == 0)
    add(1, "the file starts with a byte-order mark (save it as UTF-8 without BOM)");
  int line = 1;
  for (size_t i = 0; i < src.size(); ++i) {
    const unsigned char c = src[i];
    if (c == '\n') {
      ++line;
    } else if (c == '\0') {
      add(line, "the file holds a NUL byte: not a C++ source file");
    } else if (c == '\r' && (i + 1 == src.size() || src[i + 1] != '\n')) {
      add(line, "a carriage return not followed by a line feed (line ends must be LF or CRLF)");
    } else if (c >= 0x80) {
      // A well-formed UTF-8 sequence: no overlong forms, no surrogates, nothing past U+10FFFF.
      const size_t len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
      bool ok = len > 0 && c <= 0xF4 && i + len <= src.size();
      for (size_t k = 1; ok && k < len; ++k) ok = (static_cast<unsigned char>(src[i + k]) & 0xC0) == 0x80;
      if (ok && len >= 3) {
        const unsigned char c1 = src[i + 1];
        ok = !(c == 0xE0 && c1 < 0xA0) && !(c == 0xED && c1 >= 0xA0) && !(c == 0xF0 && c1 < 0x90) &&
             !(c == 0xF4 && c1 >= 0x90);
      }
      if (!ok) {
        add(line, "bytes that are not UTF-8 (save the file as UTF-8)");
        continue;
      }
      i += len - 1;
    }
  }
  return found;
}

// A raw string literal starts where the compiler's tokenizer sees one: R,
// u8R, uR, UR or LR as a whole token, then a quote. `xR"(` is the identifier
// xR and an ordinary string.
bool raw_string_starts(const std::string& s, size_t i) {
  if (s[i] != 'R' || i + 1 >= s.size() || s[i + 1] != '"') return false;
  size_t b = i;
  while (b > 0 && ident_char(s[b - 1])) --b;
  const std::string prefix = s.substr(b, i - b);
  return prefix.empty() || prefix == "u8" || prefix == "u" || prefix == "U" || prefix == "L";
}

// A quote inside a pp-number (1'000'000) separates digits; elsewhere it
// opens a character literal.
bool digit_separator(const std::string& s, size_t i) {
  size_t b = i;
  while (b > 0 && (ident_char(s[b - 1]) || s[b - 1] == '.' || s[b - 1] == '\'')) --b;
  return b < i && (std::isdigit((unsigned char)s[b]) ||
                   (s[b] == '.' && b + 1 < i && std::isdigit((unsigned char)s[b + 1])));
}

Cleaned clean(const std::string& src) {
  // Phase 2: splices. GCC and Clang also take a backslash followed by spaces
  // or tabs before the line end as a splice (with a warning), so the scanner
  // does: otherwise `*\ ` + newline + `/` would end a comment for the
  // compiler only. from[k] is where spliced[k] was in src.
  std::string spliced;
  std::vector<int> line;
  std::vector<size_t> from;
  int ln = 1;
  for (size_t i = 0; i < src.size(); ++i) {
    if (src[i] == '\\') {
      size_t j = i + 1;
      while (j < src.size() && (src[j] == ' ' || src[j] == '\t' || src[j] == '\f' || src[j] == '\v')) ++j;
      if (j < src.size() && src[j] == '\r') ++j;
      if (j < src.size() && src[j] == '\n') {
        i = j;
        ++ln;
        continue;
      }
    }
    spliced += src[i];
    line.push_back(ln);
    from.push_back(i);
    if (src[i] == '\n') ++ln;
  }
  // Phase 3: comments and literals.
  Cleaned out;
  auto put = [&](char c, size_t at, bool literal = false) {
    out.text += c;
    out.line_of.push_back(line[at]);
    out.literal.push_back(literal);
  };
  const size_t n = spliced.size();
  for (size_t i = 0; i < n;) {
    char c = spliced[i];
    if (c == '/' && i + 1 < n && spliced[i + 1] == '/') {
      while (i < n && spliced[i] != '\n') ++i;
      put(' ', i - 1);
    } else if (c == '/' && i + 1 < n && spliced[i + 1] == '*') {
      size_t end = spliced.find("*/", i + 2);
      put(' ', i);
      i = end == std::string::npos ? n : end + 2;
    } else if (raw_string_starts(spliced, i)) {
      // Raw string R"delim( ... )delim": no escapes, no comments inside, and
      // the compiler undoes the splices between its quotes, so its end is
      // looked for in the file as written.
      const size_t quote = from[i + 1];
      const size_t open = src.find('(', quote + 1);
      const std::string delim = open == std::string::npos ? "" : src.substr(quote + 1, open - quote - 1);
      const size_t close = open == std::string::npos ? std::string::npos : src.find(")" + delim + "\"", open + 1);
      const size_t src_end = close == std::string::npos ? src.size() : close + delim.size() + 2;
      const size_t end = std::lower_bound(from.begin() + i, from.end(), src_end) - from.begin();
      out.strings.push_back({line[i], spliced.substr(i, end - i), out.text.size(), out.text.size() + end - i});
      for (size_t k = i; k < end; ++k) put(spliced[k], k, true);
      i = end;
    } else if (c == '\'' && digit_separator(spliced, i)) {
      put(c, i);
      ++i;
    } else if (c == '"' || c == '\'') {
      size_t k = i + 1;
      while (k < n && spliced[k] != c && spliced[k] != '\n') k += spliced[k] == '\\' ? 2 : 1;
      size_t end = std::min(n, k + 1);
      if (c == '"') out.strings.push_back({line[i], spliced.substr(i, end - i), out.text.size(), out.text.size() + end - i});
      // Kept as written: #include "x.h" reads its header name from here.
      for (size_t k2 = i; k2 < end; ++k2) put(spliced[k2], k2, true);
      i = end;
    } else {
      put(c, i);
      ++i;
    }
  }
  return out;
}

std::string trim(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r\f\v");
  if (a == std::string::npos) return "";
  size_t b = s.find_last_not_of(" \t\r\f\v");
  return s.substr(a, b - a + 1);
}

void check_directive(const std::string& body, int line, const std::set<std::string>& framework, SourceScan* scan) {
  size_t i = 0;
  while (i < body.size() && ident_char(body[i])) ++i;
  const std::string name = body.substr(0, i);
  // #embed (C23; GCC 15 and Clang 19 take it in C++ too) reads any file, as
  // bytes, into an initializer: the solution without a single #include.
  if (name != "include" && name != "include_next" && name != "import" && name != "embed") return;
  const std::string rest = trim(body.substr(i));
  const std::string allowed = "only the C++ standard library, GLM (<glm/...>) and the framework's headers "
                              "(\"core/vec.h\", \"render/pathtracer.h\", ...) may be included";
  if (name != "include") {
    scan->rejections.push_back({line, "#" + name + " " + rest + ": " + allowed + ", with #include"});
    return;
  }
  const bool angled = rest.size() > 2 && rest.front() == '<' && rest.find('>') == rest.size() - 1;
  const bool quoted = rest.size() > 2 && rest.front() == '"' && rest.find('"', 1) == rest.size() - 1;
  if (!angled && !quoted) {
    scan->rejections.push_back(
        {line, "#include " + rest + ": the header name must be written out as <name> or \"name\"; " + allowed});
    return;
  }
  const std::string header = rest.substr(1, rest.size() - 2);
  const bool ok = header.find("..") == std::string::npos && header.front() != '/' &&
                  (is_standard_header(header) || framework.count(header) > 0 || (angled && is_glm_header(header)));
  if (!ok) scan->rejections.push_back({line, "#include " + rest + ": " + allowed});
}

// Identifiers worth an instructor's look, with what they may be for.
const std::map<std::string, std::string>& flagged_identifiers() {
  static const std::map<std::string, std::string> m = [] {
    std::map<std::string, std::string> t;
    for (const char* s : {"fork", "vfork", "clone", "clone3", "daemon", "setsid"}) t[s] = "creates or detaches processes";
    for (const char* s : {"execl", "execle", "execlp", "execv", "execve", "execvp", "execvpe", "fexecve", "system",
                          "popen", "posix_spawn", "posix_spawnp"})
      t[s] = "runs another program";
    for (const char* s : {"kill", "killpg", "tgkill", "raise"}) t[s] = "sends signals";
    for (const char* s : {"ptrace", "process_vm_readv", "process_vm_writev", "prctl"}) t[s] = "inspects or changes processes";
    t["syscall"] = "makes raw system calls";
    for (const char* s : {"asm", "__asm", "__asm__"}) t[s] = "inline assembly";
    for (const char* s : {"dlsym", "dlvsym", "dlopen"}) t[s] = "looks up symbols at run time";
    for (const char* s : {"getenv", "secure_getenv", "setenv", "putenv", "unsetenv", "environ"})
      t[s] = "reads or changes the environment";
    for (const char* s : {"ofstream", "fstream", "fopen", "freopen", "fwrite", "fputs", "fprintf", "open", "openat",
                          "creat", "write", "pwrite", "rename", "unlink", "mkdir", "filesystem", "mmap", "dup2"})
      t[s] = "file output or descriptors";
    for (const char* s : {"exit", "_exit", "_Exit", "quick_exit", "atexit", "at_quick_exit", "abort", "terminate"})
      t[s] = "ends the process";
    for (const char* s : {"signal", "sigaction", "setjmp", "longjmp", "siglongjmp"}) t[s] = "handles signals or jumps";
    for (const char* s : {"constructor", "destructor", "init_priority"}) t[s] = "code that runs before or after main";
    // Attributes that put code where the loader runs it (.preinit_array, an
    // ifunc resolver) or one name over another.
    for (const char* s : {"section", "ifunc", "alias", "weakref"}) t[s] = "places code where the loader finds or runs it";
    // Where the linker says the program's own image begins and ends: with
    // them, code can read its whole address space (the grading key, the test
    // main's state) without naming any of it.
    for (const char* s : {"__bss_start", "_end", "etext", "_etext", "__etext", "edata", "_edata",
                          "__executable_start", "__data_start", "data_start", "__ehdr_start", "_DYNAMIC",
                          "_GLOBAL_OFFSET_TABLE_", "__init_array_start", "__init_array_end", "__fini_array_start",
                          "__fini_array_end", "__preinit_array_start", "__preinit_array_end", "__dso_handle",
                          "__libc_stack_end", "__environ", "program_invocation_name"})
      t[s] = "a linker-defined boundary of the program's own image (reads its memory by address)";
    for (const char* s : {"dl_iterate_phdr", "getauxval", "dladdr", "dladdr1", "dlinfo"})
      t[s] = "walks the program's own loaded image";
    t["memmem"] = "searches raw memory";
    t["grading"] = "names the grader's test support (pt::grading)";
    t["testing"] = "names GoogleTest's internals (::testing)";
    t["main"] = "names main";
    return t;
  }();
  return m;
}

// The text outside literals, each literal's characters made spaces: what a
// regular expression over code may see.
std::string code_only(const Cleaned& c) {
  std::string code = c.text;
  for (size_t i = 0; i < code.size(); ++i)
    if (c.literal[i] && code[i] != '\n') code[i] = ' ';
  return code;
}

size_t skip_space(const std::string& code, size_t i) {
  while (i < code.size() && std::isspace(static_cast<unsigned char>(code[i]))) ++i;
  return i;
}

// Where an integer literal other than 0 ends when one starts at i (hex or
// decimal, digit separators, suffixes), else npos.
size_t nonzero_integer_end(const std::string& code, size_t i) {
  size_t k = i;
  bool nonzero = false;
  if (code.compare(i, 2, "0x") == 0 || code.compare(i, 2, "0X") == 0) {
    for (k = i + 2; k < code.size() && (std::isxdigit(static_cast<unsigned char>(code[k])) || code[k] == '\''); ++k)
      nonzero = nonzero || (code[k] != '0' && code[k] != '\'');
  } else if (k < code.size() && code[k] >= '1' && code[k] <= '9') {
    nonzero = true;
    while (k < code.size() && (std::isdigit(static_cast<unsigned char>(code[k])) || code[k] == '\'')) ++k;
  }
  if (!nonzero) return std::string::npos;
  while (k < code.size() && std::strchr("uUlL", code[k]) && code[k] != '\0') ++k;
  return k < code.size() && ident_char(code[k]) ? std::string::npos : k;
}

// After a cast's closing `)` or `>`: `(`, a cast to an integer type such
// as `(uintptr_t)`, another `(`, then the literal.
bool integer_follows(const std::string& code, size_t i) {
  for (int step = 0; step < 3; ++step) {
    i = skip_space(code, i);
    if (i >= code.size() || code[i] != '(') break;
    size_t k = skip_space(code, i + 1);
    const size_t name = k;
    if (k < code.size() && !std::isdigit(static_cast<unsigned char>(code[k])))
      while (k < code.size() && (ident_char(code[k]) || code[k] == ':')) ++k;
    k = skip_space(code, k);
    i = k > name && k < code.size() && code[k] == ')' ? k + 1 : i + 1;  // a cast to an integer type, or a parenthesis
  }
  return nonzero_integer_end(code, skip_space(code, i)) != std::string::npos;
}

// An integer made a pointer: `(const char*)0x400000`,
// `reinterpret_cast<uint8_t*>(4194304)`, through a cast to uintptr_t or not.
// A null pointer written as 0 is not one. Read by hand, in one pass: a
// regular expression's matcher recurses per character, and a hostile
// megabyte of spaces would overflow its stack.
template <class Flag>
void flag_address_casts(const Cleaned& c, Flag&& flag) {
  const std::string code = code_only(c);
  for (size_t i = 0; i < code.size(); ++i) {
    size_t after = std::string::npos;
    if (code[i] == '*') {
      const size_t close = skip_space(code, i + 1);
      if (close < code.size() && code[close] == ')') after = close + 1;
    } else if (code.compare(i, 16, "reinterpret_cast") == 0 && (i == 0 || !ident_char(code[i - 1]))) {
      size_t open = skip_space(code, i + 16);
      if (open < code.size() && code[open] == '<') {
        const size_t close = code.find_first_of("<>;", open + 1);
        if (close != std::string::npos && code[close] == '>') {
          size_t last = close;
          while (last > open && std::isspace(static_cast<unsigned char>(code[last - 1]))) --last;
          if (code[last - 1] == '*') after = close + 1;
        }
      }
    }
    if (after != std::string::npos && integer_follows(code, after))
      flag(c.line_of[i], "an integer made a pointer: reads memory at a fixed address");
  }
}

// `##` builds names the scanner cannot see written out: `gra ## ding`, or a
// pasting macro called as CAT(gra, ding). The pieces of each paste (in a
// #define) and of each call of a pasting macro are joined and looked for
// the framework's and the grader's names.
template <class Flag>
void flag_pasted_names(const Cleaned& c, Flag&& flag) {
  static const std::vector<std::string> names = {
      "grading", "testing", "gtest", "register_test", "Test", "incbin", "include", "preinit", "ifunc",
      "constructor", "syscall", "fork", "exec", "proc", "asm", "main", "seed", "environ", "dlsym", "reference"};
  const std::string code = code_only(c);
  auto words_in = [&](size_t from, size_t to) {
    std::string joined;
    for (size_t k = from; k < to; ++k)
      if (ident_char(code[k])) joined += code[k];
    return joined;
  };
  auto check = [&](const std::string& joined, int line, const std::string& how) {
    for (const auto& n : names)
      if (joined.find(n) != std::string::npos) {
        flag(line, "## pastes together \"" + n + "\"" + how);
        return;
      }
  };
  auto identifier_at = [&](size_t& k) {
    const size_t from = k;
    while (k < code.size() && ident_char(code[k])) ++k;
    return code.substr(from, k - from);
  };
  std::set<std::string> pasting;  // macros whose body pastes
  for (size_t start = 0; start < code.size();) {
    size_t end = code.find('\n', start);
    if (end == std::string::npos) end = code.size();
    size_t k = code.find_first_not_of(" \t\r\f\v", start);
    if (k < end && (code[k] == '#' || code.compare(k, 2, "%:") == 0)) {
      k = code.find_first_not_of(" \t\r\f\v", k + (code[k] == '#' ? 1 : 2));
      if (k < end && identifier_at(k) == "define") {
        k = code.find_first_not_of(" \t\r\f\v", k);
        const std::string name = k < end ? identifier_at(k) : "";
        const size_t paste = code.find("##", k);
        if (!name.empty() && paste < end) {
          pasting.insert(name);
          check(words_in(k, end), c.line_of[k], " in a macro");
        }
      }
    }
    start = end + 1;
  }
  if (pasting.empty()) return;
  for (size_t i = 0; i < code.size();) {
    if (!ident_char(code[i]) || (i > 0 && ident_char(code[i - 1]))) {
      ++i;
      continue;
    }
    const size_t at = i;
    const std::string id = identifier_at(i);
    if (!pasting.count(id)) continue;
    size_t k = skip_space(code, i);
    if (k >= code.size() || code[k] != '(') continue;
    // A name is built from a few short pieces: 256 bytes of arguments is plenty,
    // and nested calls of a megabyte each would cost their square.
    const size_t limit = std::min(code.size(), k + 256);
    for (int depth = 1; ++k < limit && depth > 0;) depth += code[k] == '(' ? 1 : code[k] == ')' ? -1 : 0;
    check(words_in(i, k), c.line_of[at], " from the arguments of " + id);
  }
}

}  // namespace

bool is_standard_header(const std::string& name) { return standard_headers().count(name) > 0; }

SourceScan scan_task_source(const std::string& text, const std::set<std::string>& framework_headers) {
  SourceScan scan;
  scan.rejections = encoding_problems(text);
  if (!scan.rejections.empty()) return scan;
  const Cleaned c = clean(text);
  // Directives: a logical line whose first token is # or %:.
  size_t start = 0;
  while (start < c.text.size()) {
    size_t end = c.text.find('\n', start);
    if (end == std::string::npos) end = c.text.size();
    size_t first = c.text.find_first_not_of(" \t\r\f\v", start);
    // A line that starts inside a raw string literal is not a directive.
    const bool in_literal = first < end && c.literal[first];
    std::string l = in_literal ? "" : trim(c.text.substr(start, end - start));
    std::string body;
    if (l.rfind("#", 0) == 0) body = trim(l.substr(1));
    else if (l.rfind("%:", 0) == 0) body = trim(l.substr(2));
    else l.clear();
    if (!l.empty()) check_directive(body, c.line_of[start], framework_headers, &scan);
    start = end + 1;
  }
  // Identifiers (outside comments and literals).
  const auto& flagged = flagged_identifiers();
  std::set<std::pair<int, std::string>> seen;
  auto flag = [&](int line, const std::string& what) {
    if (seen.insert({line, what}).second) scan.flags.push_back({line, what});
  };
  const std::string& t = c.text;
  for (size_t i = 0; i < t.size();) {
    if (c.literal[i] || !ident_char(t[i]) || std::isdigit((unsigned char)t[i])) {
      ++i;
      continue;
    }
    size_t j = i;
    while (j < t.size() && ident_char(t[j]) && !c.literal[j]) ++j;
    const std::string id = t.substr(i, j - i);
    const int line = c.line_of[i];
    size_t k = j;
    while (k < t.size() && std::isspace((unsigned char)t[k])) ++k;
    const bool call = k < t.size() && t[k] == '(';
    // `test` alone is a common word; pt::test and `namespace test` are not.
    size_t b = i;
    while (b > 0 && std::isspace((unsigned char)t[b - 1])) --b;
    const bool after_pt = b >= 4 && t.compare(b - 4, 4, "pt::") == 0;
    const bool before_scope = k + 1 < t.size() && t[k] == ':' && t[k + 1] == ':';
    const bool after_namespace = b >= 9 && t.compare(b - 9, 9, "namespace") == 0;
    if (id == "test" && (after_pt || before_scope || after_namespace))
      flag(line, "test: names the grader's test support (pt::test)");
    auto it = flagged.find(id);
    if (it != flagged.end() && (id != "main" || call) && (id != "open" || call) && (id != "write" || call))
      flag(line, id + ": " + it->second);
    if (id == "__has_include") flag(line, "__has_include: probes which files exist");
    // `end` is everywhere (v.end()); declared as a variable of its own it is
    // the linker's end of the program's data.
    if (id == "end" && b > 0 && ident_char(t[b - 1]) && !after_pt) {
      size_t w = b;
      while (w > 0 && ident_char(t[w - 1])) --w;
      const std::string before = t.substr(w, b - w);
      static const std::set<std::string> types = {"char", "int", "long", "void", "short", "unsigned", "signed",
                                                   "uint8_t", "uintptr_t", "byte", "extern"};
      if (types.count(before) && k < t.size() && (t[k] == '[' || t[k] == ';'))
        flag(line, "end: a linker-defined boundary of the program's own image (reads its memory by address)");
    }
    i = j;
  }
  flag_address_casts(c, flag);
  flag_pasted_names(c, flag);
  // In an asm statement these make the assembler read a file while the
  // submission is built (.incbin copies any file into the binary). The
  // assembler reads directives in any case, and the compiler joins adjacent
  // literals (".inc" "bin"), so each run of them is read joined, in lower
  // case. No scan finds them all (the preprocessor can paste the name
  // together, an assembler macro too): the kit's build runs confined
  // (kit_build.h), which is what stops the rest.
  for (size_t i = 0; i < c.strings.size();) {
    std::string joined = c.strings[i].text;
    size_t j = i + 1;
    for (; j < c.strings.size(); ++j) {
      const size_t gap = c.strings[j - 1].end;
      if (c.text.find_first_not_of(" \t\r\n\f\v", gap) != c.strings[j].begin) break;
      joined += c.strings[j].text;
    }
    std::string words, lower;
    for (size_t k = 0; k < joined.size(); ++k) {
      // The quotes (and prefixes) between the joined literals go; the words stay.
      if (joined[k] == '"') continue;
      words += joined[k];
      lower += static_cast<char>(std::tolower(static_cast<unsigned char>(joined[k])));
    }
    // The process's own files, however the path is split across literals
    // ("/pr" "oc/self/mem"), or built at run time from its pieces.
    for (const char* piece : {"/proc", "proc/", "self/", "/mem", "/maps", "/exe", "/auxv", "/pagemap"})
      if (words.find(piece) != std::string::npos) {
        flag(c.strings[i].line, "\"" + std::string(piece) + "\": reads the process's own files (/proc/self)");
        break;
      }
    if (lower.find("incbin") != std::string::npos || lower.find(".include") != std::string::npos)
      scan.rejections.push_back(
          {c.strings[i].line, "the assembler directive .incbin or .include reads a file at compile time"});
    i = j;
  }
  std::sort(scan.flags.begin(), scan.flags.end(),
            [](const SourceFinding& a, const SourceFinding& b) { return a.line < b.line; });
  return scan;
}

}  // namespace pt::grade
