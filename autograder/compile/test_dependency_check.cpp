// The compiler's own list of what a task file read, checked against what the
// header probe (autograder/compile/header_probe.cpp) read on the same compiler:
// every #include, however it is written, shows up here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "compile/dependency_check.h"

namespace pt::grade {
namespace {

namespace fs = std::filesystem;

// A ninja build that only preprocesses, as the kit's probe does, keeping the
// compiler's dependency output (deps = gcc) for `ninja -t deps`.
class DependencyCheck : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pt-deps-test-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "tasks");
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }

  void build(const std::vector<std::string>& sources) {
    std::string ninja = "rule pp\n  command = c++ -std=gnu++17 -E -w -MD -MF $out.d -o $out $in\n  deps = gcc\n"
                        "  depfile = $out.d\n";
    for (const auto& s : sources) ninja += "build " + s + ".o: pp " + s + "\n";
    write("build.ninja", ninja);
    ASSERT_EQ(std::system(("ninja -C " + dir_.string() + " > /dev/null").c_str()), 0);
  }

  fs::path dir_;
};

TEST_F(DependencyCheck, GoogleTestIsRefusedTheStandardLibraryIsNot) {
  write("probe.cpp", "#include <vector>\n#include <cmath>\n");
  write("tasks/ok.cpp", "#include <vector>\n#include <cmath>\nint f() { return 1; }\n");
  write("tasks/hidden.cpp", "#include <vector>\n#include <gtest/gtest.h>\n");
  build({"probe.cpp", "tasks/ok.cpp", "tasks/hidden.cpp"});
  const std::vector<std::string> tasks = {(dir_ / "tasks").string() + "/"};
  EXPECT_TRUE(unexpected_dependencies(dir_.string(), "tasks/ok.cpp", tasks, "probe.cpp").empty());
  const auto hidden = unexpected_dependencies(dir_.string(), "tasks/hidden.cpp", tasks, "probe.cpp");
  ASSERT_FALSE(hidden.empty());
  for (const auto& h : hidden) EXPECT_FALSE(h.size() > 7 && h.compare(h.size() - 7, 7, "/vector") == 0) << h;
  EXPECT_NE(hidden[0].find("gtest/gtest.h (GoogleTest"), std::string::npos) << hidden[0];
}

TEST_F(DependencyCheck, AHeaderTheProbeDidNotOpenIsRefused) {
  // <unistd.h> and the like are read by the standard library itself; a
  // header no allowed one opens is not.
  write("probe.cpp", "#include <vector>\n");
  write("tasks/t.cpp", "#include <vector>\n#include <sys/mman.h>\n");
  build({"probe.cpp", "tasks/t.cpp"});
  const auto found = unexpected_dependencies(dir_.string(), "tasks/t.cpp", {(dir_ / "tasks").string() + "/"}, "probe.cpp");
  ASSERT_FALSE(found.empty());
  EXPECT_NE(found[0].find("sys/mman.h"), std::string::npos) << found[0];
}

// The intake reads no #include: a file outside the allowed folders is named
// however its path was written (relative, through a macro).
TEST_F(DependencyCheck, AFileOutsideTheAllowedFoldersIsRefusedHoweverNamed) {
  write("probe.cpp", "#include <vector>\n");
  fs::create_directories(dir_ / "reference");
  write("reference/solution.cpp", "int solution() { return 42; }\n");
  write("tasks/t.cpp", "#define SOLUTION \"../reference/solution.cpp\"\n#include SOLUTION\n");
  build({"probe.cpp", "tasks/t.cpp"});
  const auto found = unexpected_dependencies(dir_.string(), "tasks/t.cpp", {(dir_ / "tasks").string() + "/"}, "probe.cpp");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0], (dir_ / "reference" / "solution.cpp").string());
}

TEST_F(DependencyCheck, WithoutTheProbesRecordNothingPasses) {
  write("tasks/t.cpp", "#include <vector>\n");
  build({"tasks/t.cpp"});
  const auto found = unexpected_dependencies(dir_.string(), "tasks/t.cpp", {(dir_ / "tasks").string() + "/"}, "probe.cpp");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].find("header probe was not built"), std::string::npos) << found[0];
}

}  // namespace
}  // namespace pt::grade
