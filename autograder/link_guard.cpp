// pt-link-guard: refuses a task file's object before it is linked into a test
// binary when it could run before the test main, replace part of the test
// framework, or replace a function of the C or C++ library for the whole
// program (README.md, "Linking"). The linker alone lets a strong definition
// win over an inline or template one without a word, and lets any definition
// in the program replace a shared library's (write(), say, through which the
// test main reports its verdicts).
//
//   pt-link-guard OBJECT... --framework FILE... --libraries SHARED_LIBRARY...
//
// OBJECT: the task file's objects. FILE: the other objects and static
// libraries of the link (test main, support, tests, skeleton, GoogleTest).
// SHARED_LIBRARY: libc, libm, libstdc++, libgcc_s. Exit status 0 when the
// objects are clean, 1 when not (each reason on stderr), 2 when it could not
// tell.
#include <cxxabi.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"

namespace {

using pt::grade::run_command;

struct Symbol {
  std::string name;
  char type;
};

std::vector<Symbol> defined_symbols(const std::string& file, bool dynamic) {
  std::vector<std::string> argv{"nm", "-P", "--defined-only"};
  if (dynamic) argv.push_back("-D");
  argv.push_back(file);
  std::string out;
  if (run_command(argv, &out) != 0) throw std::runtime_error("nm could not read " + file);
  std::vector<Symbol> symbols;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    Symbol s;
    std::string type;
    if (!(words >> s.name >> type) || type.size() != 1 || s.name.back() == ':') continue;  // "member.o:" lines
    s.type = type[0];
    if (const auto at = s.name.find('@'); at != std::string::npos) s.name.resize(at);  // write@@GLIBC_2.2.5
    symbols.push_back(s);
  }
  return symbols;
}

std::vector<std::string> section_names(const std::string& file) {
  std::string out;
  if (run_command({"readelf", "-S", "-W", file}, &out) != 0) throw std::runtime_error("readelf could not read " + file);
  std::vector<std::string> names;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    const auto close = line.find(']');
    if (line.find('[') == std::string::npos || close == std::string::npos) continue;
    std::istringstream words(line.substr(close + 1));
    std::string name;
    if (words >> name) names.push_back(name);
  }
  return names;
}

std::string demangle(const std::string& name) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status), std::free);
  return status == 0 && d ? std::string(d.get()) : name;
}

bool is_global(char type) { return type >= 'A' && type <= 'Z' && type != 'U'; }
bool is_weak(char type) { return type == 'W' || type == 'V'; }
bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> objects, framework, libraries;
  std::vector<std::string>* list = &objects;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--framework")
      list = &framework;
    else if (a == "--libraries")
      list = &libraries;
    else
      list->push_back(a);
  }
  if (objects.empty()) {
    std::fprintf(stderr, "usage: pt-link-guard OBJECT... --framework FILE... --libraries SHARED_LIBRARY...\n");
    return 2;
  }
  try {
    std::set<std::string> framework_symbols, library_symbols;
    for (const auto& f : framework)
      for (const auto& s : defined_symbols(f, false))
        if (is_global(s.type)) framework_symbols.insert(s.name);
    for (const auto& f : libraries)
      for (const auto& s : defined_symbols(f, true)) library_symbols.insert(s.name);

    std::vector<std::string> problems;
    for (const auto& object : objects) {
      auto refuse = [&](const std::string& why) { problems.push_back(object + ": " + why); };
      for (const auto& section : section_names(object))
        if (starts_with(section, ".preinit_array") || section == ".init")
          refuse("has a " + section + " section: code that runs before the test main");
      for (const auto& s : defined_symbols(object, false)) {
        const std::string name = demangle(s.name);
        if (s.type == 'i') {
          refuse("defines " + name + " as an indirect function (ifunc): code that runs before the test main");
          continue;
        }
        if (!is_global(s.type)) continue;
        const bool strong = !is_weak(s.type);
        if (s.name == "main")
          refuse("defines main()");
        else if (strong && (starts_with(name, "pt::grading::") || starts_with(name, "pt::test::") ||
                            starts_with(name, "testing::")))
          refuse("defines " + name + ", which belongs to the test framework");
        else if (strong && framework_symbols.count(s.name))
          refuse("defines " + name + ", which the test framework or the skeleton defines: it would replace theirs");
        else if ((strong || !starts_with(s.name, "_Z")) && library_symbols.count(s.name))
          refuse("defines " + name + ", which the C or C++ library defines: it would replace the library's everywhere");
      }
    }
    if (problems.empty()) return 0;
    for (const auto& p : problems) std::fprintf(stderr, "pt-link-guard: %s\n", p.c_str());
    std::fprintf(stderr,
                 "pt-link-guard: a task file defines the task functions and its own helpers, nothing else "
                 "(autograder/README.md)\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-link-guard: %s\n", e.what());
    return 2;
  }
}
