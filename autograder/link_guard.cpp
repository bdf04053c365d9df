// pt-link-guard: refuses a task file's object before it is linked into a test
// binary when it could run before the test main, replace part of the test
// framework, or replace a function of the C or C++ library for the whole
// program (README.md, "Linking"). The linker alone lets a strong definition
// win over an inline or template one without a word, and lets any definition
// in the program replace a shared library's (write(), say, through which the
// test main reports its verdicts).
//
//   pt-link-guard OBJECT... --tests FILE... --framework FILE... --libraries SHARED_LIBRARY...
//                 [--solutions FILE...]
//
// OBJECT: the task file's objects (partN_*.o: the N says whose). --tests: the
// test side of the link (test main, support, the tests, GoogleTest);
// --framework: the rest (skeleton, the other parts' solution); --solutions:
// the other parts' solutions again (partM in each name), whose functions a
// task file calls only where part_calls.h says its part may.
// SHARED_LIBRARY: libc, libm, libstdc++, libgcc_s. Exit status 0 when the
// objects are clean, 1 when not (each reason on stderr), 2 when it could not
// tell.
#include <cxxabi.h>

#include <cctype>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"
#include "part_calls.h"

namespace {

using pt::grade::run_command;

struct Symbol {
  std::string name;
  char type;
};

// The symbols of every file in `files`, from one nm: a process per file cost
// a tenth of a second each, four seconds per link of a test binary (measured).
std::vector<Symbol> symbols(const std::vector<std::string>& files, bool dynamic, bool defined) {
  if (files.empty()) return {};
  std::vector<std::string> argv{"nm", "-P", defined ? "--defined-only" : "--undefined-only"};
  if (dynamic) argv.push_back("-D");
  argv.insert(argv.end(), files.begin(), files.end());
  std::string out;
  if (run_command(argv, &out) != 0)
    throw std::runtime_error("nm could not read " + (files.size() == 1 ? files[0] : "one of " + files[0] + " ..."));
  std::vector<Symbol> symbols;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    Symbol s;
    std::string type;
    if (!(words >> s.name >> type) || type.size() != 1 || s.name.back() == ':') continue;  // "file:", "a.a[m.o]:" lines
    s.type = type[0];
    if (const auto at = s.name.find('@'); at != std::string::npos) s.name.resize(at);  // write@@GLIBC_2.2.5
    symbols.push_back(s);
  }
  return symbols;
}
std::vector<Symbol> defined_symbols(const std::vector<std::string>& files, bool dynamic) {
  return symbols(files, dynamic, true);
}

// readelf's report on `file` (`what`: -S the sections, -g the groups).
std::string readelf(const std::string& what, const std::string& file) {
  std::string out;
  if (run_command({"readelf", what, "-W", file}, &out) != 0) throw std::runtime_error("readelf could not read " + file);
  return out;
}

std::vector<std::string> section_names(const std::string& file) {
  std::vector<std::string> names;
  std::istringstream in(readelf("-S", file));
  for (std::string line; std::getline(in, line);) {
    const auto close = line.find(']');
    if (line.find('[') == std::string::npos || close == std::string::npos) continue;
    std::istringstream words(line.substr(close + 1));
    std::string name;
    if (words >> name) names.push_back(name);
  }
  return names;
}

// The signatures of the object's COMDAT groups: the inline functions and
// template instantiations the compiler made, each kept once in the program.
std::set<std::string> comdat_signatures(const std::string& file) {
  std::set<std::string> names;
  std::istringstream in(readelf("-g", file));
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("COMDAT group section", 0) != 0) continue;
    // COMDAT group section [    1] `.group' [SIGNATURE] contains 1 sections:
    const auto open = line.find("' [");
    if (open == std::string::npos) continue;
    const auto close = line.find(']', open + 3);
    if (close != std::string::npos) names.insert(line.substr(open + 3, close - open - 3));
  }
  return names;
}

std::string demangle(const std::string& name) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status), std::free);
  return status == 0 && d ? std::string(d.get()) : name;
}

// 'u': a GNU unique symbol (a static member or local of an inline function
// or template), one copy for the whole process, like a weak one.
bool is_global(char type) { return (type >= 'A' && type <= 'Z' && type != 'U') || type == 'u'; }
bool is_weak(char type) { return type == 'W' || type == 'V' || type == 'u'; }
bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The namespaces that are not a task file's: the test support's
// (tests/support/), GoogleTest's, the process boundary's (the worker's own
// code, autograder/boundary/) and the grader's. The framework (skeleton/)
// uses pt:: alone.
const char* const kTestNamespaces[] = {"pt::test::",  "pt::grading::", "pt::library::", "pt::error_model::",
                                       "pt::stats::", "testing::",     "pt::boundary::", "pt::grade::"};

// The part a file is of, from its name (part3_direct_lighting.cpp.o,
// libpt_part3_reference.a), or 0.
int part_of(const std::string& path) {
  const std::string name = path.substr(path.find_last_of('/') + 1);
  for (size_t at = name.find("part"); at != std::string::npos; at = name.find("part", at + 1))
    if (at + 4 < name.size() && std::isdigit(static_cast<unsigned char>(name[at + 4])) &&
        (at + 5 == name.size() || !std::isdigit(static_cast<unsigned char>(name[at + 5]))))
      return name[at + 4] - '0';
  return 0;
}

// Whether part `part`'s handout lets its tasks call `demangled`, another
// part's solution function (part_calls.h).
bool may_call(int part, const std::string& demangled) {
  for (const auto& c : pt::grade::kSolutionCalls)
    if (c.part == part && demangled.rfind(c.function, 0) == 0) return true;
  return false;
}

// The test-side namespace a demangled name mentions anywhere (its own scope,
// a template argument, a parameter type), or "".
std::string test_namespace_in(const std::string& demangled) {
  for (const char* ns : kTestNamespaces)
    for (size_t at = demangled.find(ns); at != std::string::npos; at = demangled.find(ns, at + 1))
      if (at == 0 || !(std::isalnum(static_cast<unsigned char>(demangled[at - 1])) || demangled[at - 1] == '_' ||
                       demangled[at - 1] == ':'))
        return std::string(ns, std::strlen(ns) - 2);
  return "";
}

// The outermost scope of a mangled name ("std", "glm", "pt", "" for a global
// or unscoped name) and, under pt, the next one: enough to tell an
// instantiation of the standard library, GLM or the framework's headers.
std::pair<std::string, std::string> mangled_scope(const std::string& m) {
  size_t p = 2;  // after _Z
  if (m.compare(0, 2, "_Z") != 0) return {"", ""};
  // Special names of a type or an entity: vtable, VTT, typeinfo and its name,
  // a thread_local's init and wrapper functions, guard variable, a lifetime-
  // extended temporary, a local entity's enclosing function.
  for (const char* special : {"TV", "TT", "TI", "TS", "TH", "TW", "GV", "GR", "Z"})
    if (m.compare(p, std::strlen(special), special) == 0) {
      p += std::strlen(special);
      break;
    }
  const bool nested = p < m.size() && m[p] == 'N';
  if (nested) ++p;
  while (p < m.size() && (m[p] == 'r' || m[p] == 'V' || m[p] == 'K')) ++p;
  if (p < m.size() && (m[p] == 'R' || m[p] == 'O')) ++p;
  if (m.compare(p, 2, "St") == 0) return {"std", ""};
  if (p + 1 < m.size() && m[p] == 'S' && std::strchr("absiod", m[p + 1])) return {"std", ""};  // Sa: std::allocator, ...
  auto component = [&](size_t& at) {
    size_t len = 0;
    while (at < m.size() && std::isdigit(static_cast<unsigned char>(m[at]))) len = len * 10 + (m[at++] - '0');
    std::string name = m.substr(at, len);
    at += len;
    return name;
  };
  if (p >= m.size() || !std::isdigit(static_cast<unsigned char>(m[p]))) return {"", ""};
  std::string first = component(p);
  if (!nested) return {"", ""};  // a global function or variable: no scope
  std::string second = p < m.size() && std::isdigit(static_cast<unsigned char>(m[p])) ? component(p) : "";
  return {first, second};
}

// An inline or template definition that any file including the standard
// library, GLM or the framework's headers makes: the task's copy and the
// tests' copy are the same code, and the task's, linked last, is discarded.
bool header_instantiation(const std::string& mangled) {
  // The compiler's own: the reference to the C++ personality routine that
  // every object with exception handling holds.
  if (starts_with(mangled, "DW.ref.")) return true;
  const auto [first, second] = mangled_scope(mangled);
  if (first == "std" || first == "__gnu_cxx" || first == "__cxxabiv1" || first == "glm") return true;
  if (first != "pt") return false;
  for (const char* ns : kTestNamespaces)
    if (starts_with(ns, "pt::") && second + "::" == std::string(ns + 4)) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> objects, tests, framework, libraries, solutions;
  std::vector<std::string>* list = &objects;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--tests")
      list = &tests;
    else if (a == "--framework")
      list = &framework;
    else if (a == "--libraries")
      list = &libraries;
    else if (a == "--solutions")
      list = &solutions;
    else
      list->push_back(a);
  }
  if (objects.empty()) {
    std::fprintf(stderr,
                 "usage: pt-link-guard OBJECT... --tests FILE... --framework FILE... --libraries SHARED_LIBRARY...\n");
    return 2;
  }
  try {
    std::set<std::string> test_symbols, framework_symbols, library_symbols;
    for (const auto& s : defined_symbols(tests, false))
      if (is_global(s.type)) test_symbols.insert(s.name);
    for (const auto& s : defined_symbols(framework, false))
      if (is_global(s.type)) framework_symbols.insert(s.name);
    for (const auto& s : defined_symbols(libraries, true)) library_symbols.insert(s.name);
    std::map<std::string, int> solution_symbols;  // what another part's solution defines -> that part
    for (const auto& f : solutions)
      for (const auto& s : defined_symbols({f}, false))
        if (is_global(s.type) && !is_weak(s.type)) solution_symbols.emplace(s.name, part_of(f));

    std::vector<std::string> problems;
    for (const auto& object : objects) {
      auto refuse = [&](const std::string& why) { problems.push_back(object + ": " + why); };
      for (const auto& section : section_names(object))
        if (starts_with(section, ".preinit_array") || section == ".init")
          refuse("has a " + section + " section: code that runs before the test main");
      const std::set<std::string> comdat = comdat_signatures(object);
      for (const auto& s : defined_symbols({object}, false)) {
        const std::string name = demangle(s.name);
        if (s.type == 'i') {
          refuse("defines " + name + " as an indirect function (ifunc): code that runs before the test main");
          continue;
        }
        if (!is_global(s.type)) continue;  // internal linkage: the task file's own
        const bool strong = !is_weak(s.type);
        const std::string kind = strong ? "defines " : "defines an inline or weak copy of ";
        const std::string test_ns = test_namespace_in(name);
        if (s.name == "main")
          refuse("defines main()");
        else if (!test_ns.empty())
          refuse(kind + name + ", in " + test_ns +
                 ", which belongs to the tests, their support, GoogleTest, the process boundary or the grader");
        else if (test_symbols.count(s.name) && (strong || !header_instantiation(s.name)))
          refuse(kind + name + ", which the tests or their support define: it could replace theirs");
        else if (strong && framework_symbols.count(s.name))
          refuse("defines " + name + ", which the test framework or the skeleton defines: it would replace theirs");
        // A definition in the program, even a weak one, replaces a shared
        // library's for every caller (std::string::_M_append, say, which the
        // boundary's link sends its answers through). The compiler's own
        // copies of the headers' inline functions are COMDAT groups (std::endl
        // makes std::ctype<char>::do_widen): those are the headers' code; a
        // weak definition outside a group is the task file's own.
        else if (library_symbols.count(s.name) && (strong || !comdat.count(s.name)))
          refuse((strong ? "defines " : "defines a weak ") + name +
                 ", which the C or C++ library exports: it would replace the library's everywhere");
      }
      // What the task file uses must come from the framework or the
      // libraries: the tests' own code (the support's BVH builder, its
      // expected values, GoogleTest's registry) is not the task's to call.
      for (const auto& s : symbols({object}, false, false)) {
        if (test_symbols.count(s.name) && !framework_symbols.count(s.name) && !library_symbols.count(s.name))
          refuse("uses " + demangle(s.name) + ", which only the tests, their support or GoogleTest define");
        const std::string name = demangle(s.name);
        for (const auto& answer : pt::grade::kTaskAnswers)
          if (starts_with(name, answer.function))
            refuse("uses " + name + ", the framework's own answer to " + answer.task + ": write it yourself");
        // Another part's solution: only what this part's handout specifies.
        const int part = part_of(object);
        if (auto it = solution_symbols.find(s.name); it != solution_symbols.end() && !may_call(part, name))
          refuse("uses " + name + ", part " + std::to_string(it->second) + "'s solution, which part " +
                 std::to_string(part) + "'s tasks are not specified to call (autograder/part_calls.h)");
      }
    }
    if (problems.empty()) return 0;
    for (const auto& p : problems) std::fprintf(stderr, "pt-link-guard: %s\n", p.c_str());
    std::fprintf(stderr,
                 "pt-link-guard: a task file defines the task functions and its own helpers, nothing else, and "
                 "calls the framework and the C++ library, not the tests (autograder/README.md, \"Linking\")\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-link-guard: %s\n", e.what());
    return 2;
  }
}
