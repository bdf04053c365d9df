#pragma once
// What `pt-grade submission` reads in a task file before it builds anything
// (autograder/README.md has the threat model):
//
//  * Rejections: a file that is not UTF-8, starts with a byte-order mark,
//    holds a NUL or a CR not followed by LF (the compiler would read its
//    lines differently: each named with its line, nothing else is read);
//    an #include of anything but the C++ standard library, GLM
//    and the framework's headers; #include_next, #import and #embed; an
//    #include whose header name is computed by a macro or cannot be read
//    plainly; the assembler's .incbin or .include in a string (asm
//    statements read files at compile time with them). A rejected
//    file is not compiled: its part scores 0, with the reasons.
//  * Flags, for an instructor to read (they never change a score): process
//    control (fork, exec*, kill, ptrace, syscall, exit), asm, dlsym, "/proc",
//    the environment, file output, signal handlers, constructor, section and
//    ifunc attributes, names of the test support (pt::grading, pt::test,
//    ::testing), a definition of main; reads of the program's own memory by
//    address (the linker's boundary symbols, dl_iterate_phdr, memmem, an
//    integer made a pointer, /proc/self); names built with ##.
//
// The scanner follows the preprocessor's first phases (line splices, with
// spaces before the line end as GCC takes them; comments; string literals;
// raw string literals where the tokenizer sees one, ended as the compiler
// ends them, splices undone; digit separators; the %: digraph), so that a
// directive cannot hide from it in a way the compiler would still honour; what
// it cannot read plainly it rejects. The build then checks what the compiler
// actually opened (its dependency list), which catches anything this misses.
#include <set>
#include <string>
#include <vector>

namespace pt::grade {

struct SourceFinding {
  int line = 0;      // 1-based, in the file as submitted
  std::string what;  // e.g. "#include of \"../reference/part1.cpp\": only ..."
};

struct SourceScan {
  std::vector<SourceFinding> rejections;
  std::vector<SourceFinding> flags;
};

// `framework_headers`: the headers a task file may include by their path
// relative to the framework's include directory ("core/vec.h", ...).
SourceScan scan_task_source(const std::string& text, const std::set<std::string>& framework_headers);

// A header of the C++17 standard library (<vector>, <cmath>, <math.h>, ...).
bool is_standard_header(const std::string& name);
// All of them (the kit's header probe, autograder/header_probe.cpp,
// includes each).
const std::set<std::string>& standard_headers();

}  // namespace pt::grade
