#pragma once
// The directives that make the compiler or the assembler read a file as data
// while a task file is built: #embed (C23; GCC 15 and Clang 19 take it in C++
// too), and the assembler's .incbin and .include in an asm statement's
// string. What the compiler opens as a header the build's dependency check
// sees (compile/dependency_check.h); what the assembler reads it never lists.
// Landlock on the kit's build is what holds against the forms no text search
// finds (a name pasted by the preprocessor or by an assembler macro); this is
// depth behind it, for the plain forms where Landlock is missing
// (autograder/README.md, the threat model).
//
// The file is searched as bytes, comments included, after the compiler's
// line splices are undone and adjacent string literals joined (".inc" "bin"):
// no tokens and no lines to read differently from the compiler, so nothing
// to hide a directive from it with a byte-order mark or a lone CR.
#include <string>
#include <vector>

namespace pt::grade {

struct FileDirective {
  int line = 0;      // 1-based, in the file as submitted
  std::string what;  // what it reads, for the student and the report
};

// Each line holding one of the directives above, once per kind.
std::vector<FileDirective> file_directives(const std::string& text);

}  // namespace pt::grade
