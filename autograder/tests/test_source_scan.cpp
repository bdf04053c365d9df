// What pt-grade submission rejects and flags in a task file before building it.
#include <gtest/gtest.h>

#include "source_scan.h"

namespace pt::grade {
namespace {

const std::set<std::string> kFramework = {"core/vec.h", "render/pathtracer.h", "geometry/bvh.h",
                                          "core/not_implemented.h"};

std::string lines(const std::vector<SourceFinding>& found) {
  std::string s;
  for (const auto& f : found) s += std::to_string(f.line) + ": " + f.what + "\n";
  return s;
}

bool mentions(const std::vector<SourceFinding>& found, const std::string& text, int line = 0) {
  for (const auto& f : found)
    if (f.what.find(text) != std::string::npos && (line == 0 || f.line == line)) return true;
  return false;
}

TEST(SourceScan, StandardGlmAndFrameworkIncludesAreAccepted) {
  const std::string src =
      "#include <cmath>\n#include <vector>\n#  include <math.h>\n%:include <algorithm>\n"
      "#include \"core/vec.h\"\n#include <render/pathtracer.h>\n#include <glm/gtx/norm.hpp>\n"
      "#include \"cstdio\" // a standard header in quotes still finds the standard one\n"
      "#include /* a comment */ <array>\n";
  SourceScan s = scan_task_source(src, kFramework);
  EXPECT_TRUE(s.rejections.empty()) << lines(s.rejections);
}

TEST(SourceScan, IncludesOfAnythingElseAreRejectedWithTheirLine) {
  struct Case {
    std::string src;
    int line;
  };
  const std::vector<Case> cases = {
      {"#include \"../reference/part1_raygen_intersect.cpp\"\n", 1},
      {"int x;\n#include \"/work/main/reference/part1_raygen_intersect.cpp\"\n", 2},
      {"#include <support/graded.h>\n", 1},
      {"#include \"scene.h\"\n", 1},  // not a path the framework has
      {"#include <bits/stdc++.h>\n", 1},
      {"#include <unistd.h>\n", 1},
      {"#define F \"../reference/x.cpp\"\n#include F\n", 2},  // computed
      {"#include_next <cmath>\n", 1},
      {"#import \"core/vec.h\"\n", 1},
      // C23's #embed (GCC 15, Clang 19) reads any file into an initializer.
      {"const char s[] = {\n#embed \"../reference/x.cpp\"\n};\n", 2},
      {"#include <glm/../../reference/x.cpp>\n", 1},
      // A splice joins the two lines for the preprocessor, and so for the scanner.
      {"#inc\\\nlude \"../reference/x.cpp\"\n", 1},
      // A block comment spanning lines is one space: the directive goes on.
      {"#include /*\n*/ \"../reference/x.cpp\"\n", 1},
      {"%:include \"../reference/x.cpp\"\n", 1},
      {"int x;\nasm(\".incbin \\\"/work/main/reference/part1.cpp\\\"\");\n", 2},
      {"asm(\".include \\\"x.s\\\"\");\n", 1},
      // The assembler reads its directives in any case, and the compiler
      // joins adjacent literals before the assembler sees them.
      {"asm(\".INCBIN \\\"/etc/passwd\\\"\");\n", 1},
      {"asm(\".inc\"\n    \"bin \\\"/etc/passwd\\\"\");\n", 1},
  };
  for (const auto& c : cases) {
    SourceScan s = scan_task_source(c.src, kFramework);
    EXPECT_FALSE(s.rejections.empty()) << "accepted:\n" << c.src;
    if (!s.rejections.empty()) {
      EXPECT_EQ(s.rejections[0].line, c.line) << c.src << lines(s.rejections);
    }
  }
}

TEST(SourceScan, TextThatOnlyLooksLikeADirectiveIsNotOne) {
  const std::string src =
      "const char* a = \"#include <unistd.h>\";\n"
      "// #include \"../reference/x.cpp\"\n"
      "/* #include \"../reference/x.cpp\" */\n"
      "const char* b = R\"(\n#include \"../reference/x.cpp\"\n)\";\n";
  SourceScan s = scan_task_source(src, kFramework);
  EXPECT_TRUE(s.rejections.empty()) << lines(s.rejections);
}

TEST(SourceScan, NulBytesAreRejected) {
  SourceScan s = scan_task_source(std::string("int x;\0int y;", 13), kFramework);
  EXPECT_TRUE(mentions(s.rejections, "NUL"));
}

TEST(SourceScan, FlagsWhatAnInstructorShouldRead) {
  const std::string src =
      "#include <cstdlib>\n"                                         // 1
      "static int pid = fork();\n"                                   // 2
      "void f() { execv(\"/bin/sh\", nullptr); }\n"                  // 3
      "void g() { kill(1, 9); }\n"                                   // 4
      "long h() { return syscall(39); }\n"                           // 5
      "void i() { asm(\"nop\"); }\n"                                 // 6
      "void* j() { return dlsym(nullptr, \"x\"); }\n"                // 7
      "const char* k = \"/proc/self/cmdline\";\n"                    // 8
      "const char* l() { return getenv(\"HOME\"); }\n"               // 9
      "void m() { std::ofstream o(\"x\"); }\n"                       // 10
      "__attribute__((constructor)) void n() {}\n"                   // 11
      "namespace pt::grading { bool register_test(); }\n"            // 12
      "namespace pt { namespace test { int seed; } }\n"              // 13
      "int main(int, char**) { return 0; }\n"                        // 14
      "void o() { std::exit(0); }\n"                                 // 15
      "void p() { ptrace(0, 0, 0, 0); }\n"                           // 16
      "__attribute__((section(\".preinit_array\"))) void (*q)() = 0;\n" // 17
      "void r() __attribute__((ifunc(\"s\")));\n";                     // 18
  SourceScan s = scan_task_source(src, kFramework);
  EXPECT_TRUE(s.rejections.empty()) << lines(s.rejections);
  const std::vector<std::pair<int, std::string>> want = {
      {2, "fork"},     {3, "execv"},        {4, "kill"},    {5, "syscall"}, {6, "asm"},
      {7, "dlsym"},    {8, "/proc"},        {9, "getenv"},  {10, "ofstream"}, {11, "constructor"},
      {12, "grading"}, {13, "test"},        {14, "main"},   {15, "exit"},    {16, "ptrace"},
      {17, "section"}, {18, "ifunc"}};
  for (const auto& [line, word] : want) EXPECT_TRUE(mentions(s.flags, word, line)) << word << "\n" << lines(s.flags);
}

TEST(SourceScan, OrdinaryTaskCodeRaisesNoFlag) {
  // Words in comments and strings, and ordinary names, are not flags.
  const std::string src =
      "#include \"render/pathtracer.h\"\n"
      "// we could fork here, or exit early; test this\n"
      "namespace pt {\n"
      "const char* msg = \"kill the ray, then exit\";\n"
      "double test_value(double main_t) { double write = main_t; return write; }\n"
      "bool Sphere::test(const Ray& ray, double& t1, double& t2) const { return test_value(t1) > 0; }\n"
      "}\n";
  SourceScan s = scan_task_source(src, kFramework);
  EXPECT_TRUE(s.flags.empty()) << lines(s.flags);
}

}  // namespace
}  // namespace pt::grade
