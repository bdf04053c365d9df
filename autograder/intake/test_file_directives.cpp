// The directives that read a file as data, found however the compiler would
// still read them: joined literals, splices, any case, comments between.
#include <gtest/gtest.h>

#include "intake/file_directives.h"

namespace pt::grade {
namespace {

std::string listed(const std::vector<FileDirective>& found) {
  std::string s;
  for (const auto& f : found) s += std::to_string(f.line) + ": " + f.what + "\n";
  return s;
}

bool found_on(const std::string& text, int line, const std::string& what) {
  for (const auto& f : file_directives(text))
    if (f.line == line && f.what.find(what) != std::string::npos) return true;
  return false;
}

TEST(FileDirectives, IncbinAndIncludeInAsmAreRefusedWithTheirLine) {
  EXPECT_TRUE(found_on("int x;\nasm(\".incbin \\\"/etc/passwd\\\"\");\n", 2, ".incbin"));
  EXPECT_TRUE(found_on("asm(\".INCBIN \\\"f\\\"\");\n", 1, ".incbin"));
  EXPECT_TRUE(found_on("int y;\nasm(\".include \\\"f.s\\\"\");\n", 2, ".include"));
}

TEST(FileDirectives, TheCompilersJoinsAndSplicesDoNotHideThem) {
  EXPECT_TRUE(found_on("asm(\".inc\" \"bin f\");\n", 1, ".incbin"));                  // adjacent literals
  EXPECT_TRUE(found_on("asm(\".inc\" /* c */\n  u8\"bin f\");\n", 1, ".incbin"));      // a comment, a prefix
  EXPECT_TRUE(found_on("asm(\".inc\" // c\n  \"bin f\");\n", 1, ".incbin"));          // a line comment
  EXPECT_TRUE(found_on("asm(\".inc\\\nbin f\");\n", 1, ".incbin"));                    // a splice
  EXPECT_TRUE(found_on("asm(\".inc\\  \r\nbin f\");\n", 1, ".incbin"));                // spaces, CRLF
  EXPECT_TRUE(found_on("int x;\rasm(\".inc\\\rbin f\");\n", 1, ".incbin"));             // lone CRs
  EXPECT_TRUE(found_on("asm(\"// \\n\"\n\"\\n.incbin f\");\n", 2, ".incbin"));        // a // inside a literal
  EXPECT_TRUE(found_on("\xEF\xBB\xBF" "asm(\".incbin f\");\n", 1, ".incbin"));         // behind a byte-order mark
}

TEST(FileDirectives, EmbedIsRefusedHoweverTheDirectiveIsSpelled) {
  EXPECT_TRUE(found_on("int a[] = {\n#embed \"/etc/passwd\"\n};\n", 2, "#embed"));
  EXPECT_TRUE(found_on("  # /* x */ embed <f>\n", 1, "#embed"));
  EXPECT_TRUE(found_on("%:embed \"f\"\n", 1, "#embed"));
  EXPECT_TRUE(found_on("#em\\\nbed \"f\"\n", 1, "#embed"));
  EXPECT_TRUE(found_on("\xEF\xBB\xBF#embed \"f\"\n", 1, "#embed"));
}

TEST(FileDirectives, OrdinaryTaskCodeIsAccepted) {
  const std::string src =
      "#include <vector>\n#include \"core/vec.h\"\n#include \"render/pathtracer.h\"\n"
      "// embedded in a scene; the include guard; #embedded\n"
      "#define EMBED_DEPTH 4\n"
      "const char* name = \"bin\"; const char* file = \"scene.obj\";\n"
      "float f(float x) { return x * 0.5f; }  // caf\xC3\xA9\r\n";
  EXPECT_TRUE(file_directives(src).empty()) << listed(file_directives(src));
}

TEST(FileDirectives, EachLineIsNamedOnce) {
  std::string src;
  for (int i = 0; i < 1000; ++i) src += "#embed \"f\" // #embed, .incbin\n";
  const auto found = file_directives(src);
  EXPECT_EQ(found.size(), 2000u);
  EXPECT_EQ(found.front().line, 1);
  EXPECT_EQ(found.back().line, 1000);
}

}  // namespace
}  // namespace pt::grade
