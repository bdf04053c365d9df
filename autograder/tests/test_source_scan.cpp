// What pt-grade submission rejects and flags in a task file before building it.
#include <gtest/gtest.h>

#include <chrono>

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

// GCC skips a byte-order mark and ends a line at a lone CR: either would make
// a directive of text the scanner reads as something else.
TEST(SourceScan, EncodingTheCompilerReadsDifferentlyIsRejectedWithTheLine) {
  SourceScan bom = scan_task_source("\xEF\xBB\xBF#include <gtest/gtest.h>\nint x;\n", kFramework);
  EXPECT_TRUE(mentions(bom.rejections, "byte-order mark", 1)) << lines(bom.rejections);
  SourceScan cr = scan_task_source("int x;\nint y;\r#include <gtest/gtest.h>\n", kFramework);
  EXPECT_TRUE(mentions(cr.rejections, "carriage return not followed by a line feed", 2)) << lines(cr.rejections);
  SourceScan latin1 = scan_task_source("int x;\n// caf\xE9\n", kFramework);
  EXPECT_TRUE(mentions(latin1.rejections, "not UTF-8", 2)) << lines(latin1.rejections);
  SourceScan overlong = scan_task_source("// \xC0\xAF\n", kFramework);  // '/' spelled in two bytes
  EXPECT_TRUE(mentions(overlong.rejections, "not UTF-8", 1)) << lines(overlong.rejections);
  SourceScan surrogate = scan_task_source("// \xED\xA0\x80\n", kFramework);
  EXPECT_TRUE(mentions(surrogate.rejections, "not UTF-8", 1)) << lines(surrogate.rejections);
  SourceScan truncated = scan_task_source("int x; // \xE2\x82", kFramework);
  EXPECT_TRUE(mentions(truncated.rejections, "not UTF-8", 1)) << lines(truncated.rejections);
}

TEST(SourceScan, CrlfAndUtf8TextAreAccepted) {
  const std::string src = "#include <cmath>\r\n// \xC2\xB5m, \xE2\x82\xAC, \xF0\x9F\x99\x82\r\nint x;\r\n";
  SourceScan s = scan_task_source(src, kFramework);
  EXPECT_TRUE(s.rejections.empty()) << lines(s.rejections);
}

// R"( starts a raw string only as a token of its own (R, u8R, uR, UR, LR):
// `fuR"(` is the identifier fuR and an ordinary string, so the line after it
// is a directive for the compiler, and must be for the scanner.
TEST(SourceScan, RawStringPrefixesAreWholeTokens) {
  const std::string hidden = "#define X(a) 0\nint z = X(fuR\"(\");\n#include <gtest/gtest.h>\n// )\"\n";
  SourceScan s = scan_task_source(hidden, kFramework);
  EXPECT_TRUE(mentions(s.rejections, "gtest", 3)) << lines(s.rejections);
  SourceScan x = scan_task_source("int z = X(xR\"(\");\n#include <unistd.h>\n// )\"\n", kFramework);
  EXPECT_TRUE(mentions(x.rejections, "unistd", 2)) << lines(x.rejections);
  for (const char* prefix : {"R", "u8R", "uR", "UR", "LR"}) {
    const std::string raw = std::string("auto s = ") + prefix + "\"(\n#include <unistd.h>\n)\";\n";
    SourceScan r = scan_task_source(raw, kFramework);
    EXPECT_TRUE(r.rejections.empty()) << prefix << "\n" << lines(r.rejections);
  }
}

// The compiler undoes line splices inside a raw string: `)x\` + newline +
// `"` does not end R"x(. The scanner must not end it there either.
TEST(SourceScan, RawStringsEndWhereTheCompilerEndsThem) {
  const std::string src = "auto a = R\"x( )x\\\n\" R\"y( )x\";\n#include <unistd.h>\n// )y\"\n";
  SourceScan s = scan_task_source(src, kFramework);
  EXPECT_TRUE(mentions(s.rejections, "unistd", 3)) << lines(s.rejections);
}

// A backslash, spaces, then the line end is a splice for GCC: `*\ ` and `/`
// on the next line close a comment.
TEST(SourceScan, SplicesWithTrailingSpacesAreSplices) {
  const std::string src = "/* a comment *\\  \n/\n#include <unistd.h>\n";
  SourceScan s = scan_task_source(src, kFramework);
  EXPECT_TRUE(mentions(s.rejections, "unistd", 3)) << lines(s.rejections);
}

// 1'000 is a number; a quote there opens no character literal that would hide
// the rest of the line from the flags.
TEST(SourceScan, DigitSeparatorsOpenNoLiteral) {
  SourceScan s = scan_task_source("long n = 1'000; long p = fork(); char c = 'x';\n", kFramework);
  EXPECT_TRUE(mentions(s.flags, "fork", 1)) << lines(s.flags);
  SourceScan u8 = scan_task_source("auto c = u8'a'; // fork\n", kFramework);
  EXPECT_TRUE(u8.flags.empty()) << lines(u8.flags);
}

// Reading the program's own memory by address: the linker's boundary symbols,
// the loader's walk of the image, an integer made a pointer, /proc/self.
TEST(SourceScan, FlagsReadsOfTheProgramsOwnMemory) {
  const std::vector<std::pair<std::string, std::string>> hits = {
      {"extern char __bss_start[];\n", "__bss_start"},
      {"extern \"C\" char etext, edata;\n", "etext"},
      {"extern char end;\n", "end"},
      {"extern \"C\" char end[];\n", "end"},
      {"auto p = &__executable_start;\n", "__executable_start"},
      {"int n = dl_iterate_phdr(cb, nullptr);\n", "dl_iterate_phdr"},
      {"long r = process_vm_readv(0, 0, 0, 0, 0, 0);\n", "process_vm_readv"},
      {"auto h = memmem(a, n, key, 8);\n", "memmem"},
      {"auto p = (const char*)0x400000;\n", "integer made a pointer"},
      {"auto p = (unsigned char *) 4194304;\n", "integer made a pointer"},
      {"auto p = reinterpret_cast<const uint8_t*>(0x55'0000'0000ull);\n", "integer made a pointer"},
      {"auto p = (char*)(uintptr_t)0x1000;\n", "integer made a pointer"},
      {"auto p = (const char*)(0x400000);\n", "integer made a pointer"},
      {"const char* f = \"/proc/self/mem\";\n", "/proc"},
      {"const char* f = \"/pr\" \"oc/self/maps\";\n", "/proc"},
      {"std::string f = std::string(\"/\") + \"self/exe\";\n", "self/"},
  };
  for (const auto& [src, word] : hits) {
    SourceScan s = scan_task_source(src, kFramework);
    EXPECT_TRUE(mentions(s.flags, word, 1)) << src << lines(s.flags);
    EXPECT_TRUE(s.rejections.empty()) << src << lines(s.rejections);
  }
  // Near misses: the same words where they mean nothing of the kind.
  const std::vector<std::string> misses = {
      "auto end = v.end(); for (auto it = v.begin(); it != end; ++it) {}\n",
      "int end = 3;\n",
      "double etext_width = 2;\n",
      "auto p = (const char*)0;\n",
      "double x = (a * b) * 4096;\n",
      "auto p = static_cast<float*>(nullptr);\n",
      "const char* s = \"processed 10 rays, /tmp\";\n",
      "auto q = memcpy(a, b, 8);\n",
  };
  for (const auto& src : misses) {
    SourceScan s = scan_task_source(src, kFramework);
    EXPECT_TRUE(s.flags.empty()) << src << lines(s.flags);
  }
}

// Token pasting that builds the framework's or the grader's names.
TEST(SourceScan, FlagsNamesBuiltByTokenPasting) {
  SourceScan body = scan_task_source("#define G pt::gra ## ding::register_test\n", kFramework);
  EXPECT_TRUE(mentions(body.flags, "## pastes together \"grading\"", 1)) << lines(body.flags);
  SourceScan call = scan_task_source("#define CAT(a, b) a##b\nnamespace pt { namespace CAT(gra, ding) {} }\n"
                                     "void f() { CAT(test, ing)::x(); }\n",
                                     kFramework);
  EXPECT_TRUE(mentions(call.flags, "\"grading\" from the arguments of CAT", 2)) << lines(call.flags);
  EXPECT_TRUE(mentions(call.flags, "\"testing\" from the arguments of CAT", 3)) << lines(call.flags);
  SourceScan miss = scan_task_source("#define CAT(a, b) a##b\nauto CAT(v, 3) = CAT(hit_, count);\n", kFramework);
  EXPECT_TRUE(miss.flags.empty()) << lines(miss.flags);
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

// A task file may be up to 1 MiB of anything: the scan must neither recurse
// per character (std::regex's matcher overflowed its stack on a 1 MB
// #define line) nor cost the square of the size.
TEST(SourceScan, AMegabyteOfHostileTextIsScannedQuickly) {
  const std::vector<std::string> texts = {
      "#define X " + std::string(1000000, 'a') + "\n",
      "int x = (char*)" + std::string(1000000, ' ') + "1;\n",
      "#define C(a, b) a##b\n" + [] {
        std::string calls;
        for (int i = 0; i < 300000; ++i) calls += "C(";
        return calls;
      }() + "\n",
      std::string(500000, '*') + std::string(500000, ')'),
  };
  for (const auto& text : texts) {
    const auto start = std::chrono::steady_clock::now();
    scan_task_source(text, kFramework);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0)
        << text.substr(0, 40);
  }
}

}  // namespace
}  // namespace pt::grade
