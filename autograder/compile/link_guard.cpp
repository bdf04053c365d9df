// pt-link-guard: refuses a task file's object before it is linked into the
// worker (boundary/README.md: the task file's process, which holds no test)
// when it could replace part of the framework or of the boundary's own code
// there, or a function of the C or C++ library for the whole program, or
// when it calls what its part's handout does not give it (README.md,
// "Linking"). The linker alone lets a strong definition win over an inline or
// template one without a word, and lets any definition in the program replace
// a shared library's.
//
//   pt-link-guard OBJECT... --framework FILE... --libraries SHARED_LIBRARY... [--solutions FILE...]
//
// OBJECT: the task file's objects (partN_*.o: the N says whose). --framework:
// the rest of the link (skeleton, the other parts' solution, the boundary's
// worker); --solutions: the other parts' solutions again (partM in each
// name), whose functions a task file calls only where part_calls.h says its
// part may. SHARED_LIBRARY: libc, libm, libstdc++, libgcc_s. Exit status 0
// when the objects are clean, 1 when not (each reason on stderr), 2 when it
// could not tell.
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

#include "compile/part_calls.h"
#include "process/command.h"

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

// readelf's report on `file` (`what`: -g the groups).
std::string readelf(const std::string& what, const std::string& file) {
  std::string out;
  if (run_command({"readelf", what, "-W", file}, &out) != 0) throw std::runtime_error("readelf could not read " + file);
  return out;
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

// The namespaces that are not a task file's: the process boundary's (the
// worker's own code, boundary/) and the grader's. The framework (skeleton/)
// uses pt:: alone. The tests' namespaces are not here: the worker holds
// nothing of the tests, so a definition in them displaces nothing, and a use
// of them does not link.
const char* const kGraderNamespaces[] = {"pt::boundary::", "pt::grade::"};

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

// The grader's namespace a demangled name mentions anywhere (its own scope,
// a template argument, a parameter type), or "".
std::string grader_namespace_in(const std::string& demangled) {
  for (const char* ns : kGraderNamespaces)
    for (size_t at = demangled.find(ns); at != std::string::npos; at = demangled.find(ns, at + 1))
      if (at == 0 || !(std::isalnum(static_cast<unsigned char>(demangled[at - 1])) || demangled[at - 1] == '_' ||
                       demangled[at - 1] == ':'))
        return std::string(ns, std::strlen(ns) - 2);
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> objects, framework, libraries, solutions;
  std::vector<std::string>* list = &objects;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--framework")
      list = &framework;
    else if (a == "--libraries")
      list = &libraries;
    else if (a == "--solutions")
      list = &solutions;
    else
      list->push_back(a);
  }
  if (objects.empty()) {
    std::fprintf(stderr, "usage: pt-link-guard OBJECT... --framework FILE... --libraries SHARED_LIBRARY... "
                         "[--solutions FILE...]\n");
    return 2;
  }
  try {
    std::set<std::string> framework_symbols, library_symbols;
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
      const std::set<std::string> comdat = comdat_signatures(object);
      for (const auto& s : defined_symbols({object}, false)) {
        if (!is_global(s.type)) continue;  // internal linkage: the task file's own
        const std::string name = demangle(s.name);
        const bool strong = !is_weak(s.type);
        const std::string kind = strong ? "defines " : "defines an inline or weak copy of ";
        const std::string grader_ns = grader_namespace_in(name);
        if (!grader_ns.empty())
          refuse(kind + name + ", in " + grader_ns + ", which belongs to the process boundary or the grader");
        else if (strong && framework_symbols.count(s.name))
          refuse("defines " + name + ", which the framework or the boundary's worker defines: it would replace theirs");
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
      for (const auto& s : symbols({object}, false, false)) {
        const std::string name = demangle(s.name);
        for (const auto& answer : pt::grade::kTaskAnswers)
          if (starts_with(name, answer.function))
            refuse("uses " + name + ", the framework's own answer to " + answer.task + ": write it yourself");
        // Another part's solution: only what this part's handout specifies.
        const int part = part_of(object);
        if (auto it = solution_symbols.find(s.name); it != solution_symbols.end() && !may_call(part, name))
          refuse("uses " + name + ", part " + std::to_string(it->second) + "'s solution, which part " +
                 std::to_string(part) + "'s tasks are not specified to call (autograder/compile/part_calls.h)");
      }
    }
    if (problems.empty()) return 0;
    for (const auto& p : problems) std::fprintf(stderr, "pt-link-guard: %s\n", p.c_str());
    std::fprintf(stderr,
                 "pt-link-guard: a task file defines the task functions and its own helpers, nothing else, and "
                 "calls the framework and the C++ library (autograder/README.md, \"Linking\")\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-link-guard: %s\n", e.what());
    return 2;
  }
}
