// What check-submission leaves out of "added" files: the release's .gitignore.
#include <gtest/gtest.h>

#include <filesystem>

#include "intake/ignore_rules.h"
#include "pt_source_dir.h"

namespace pt::grade {
namespace {

// The release ships the checkout's .gitignore: what it says of the files the
// release's own instructions and tools create.
TEST(IgnoreRules, TheReleasesGitignoreCoversWhatItsInstructionsCreate) {
  const IgnoreRules rules = IgnoreRules::read((std::filesystem::path(PT_SOURCE_DIR) / ".gitignore").string());
  EXPECT_TRUE(rules.ignored("tests/viewer/browser/node_modules", true)) << "npm ci in tests/viewer/browser";
  EXPECT_TRUE(rules.ignored("tests/viewer/browser/node_modules/puppeteer-core/lib/cjs/index.js", false));
  EXPECT_TRUE(rules.ignored("build/tests/part1_tests", false));
  EXPECT_TRUE(rules.ignored("build-bench", true));
  EXPECT_TRUE(rules.ignored("tests/part3/mine.png", false));
  // ... and not what would change the grader's build.
  EXPECT_FALSE(rules.ignored("tests/part1/test_my_own.cpp", false));
  EXPECT_FALSE(rules.ignored("skeleton/core/my_helpers.h", false));
  EXPECT_FALSE(rules.ignored("tests/out/helper.cpp", false)) << "/out/ is the top folder only";
  EXPECT_FALSE(rules.ignored("scenes/reference/cornell_spheres.exr", false)) << "a '!' line brings it back";
}

TEST(IgnoreRules, FollowsGitsRulesForFoldersAnchorsAndNegation) {
  const IgnoreRules rules = IgnoreRules::parse(
      "# a comment\n\ncache/\n/top.txt\ndocs/*.tmp\n*.log\n!keep.log\nlocked/\n!locked/inside.cpp\n**/deep.h\n");
  EXPECT_TRUE(rules.ignored("a/cache", true));
  EXPECT_TRUE(rules.ignored("a/cache/x.cpp", false)) << "below an ignored folder";
  EXPECT_FALSE(rules.ignored("a/cache", false)) << "a trailing '/' matches folders only";
  EXPECT_TRUE(rules.ignored("top.txt", false));
  EXPECT_FALSE(rules.ignored("sub/top.txt", false)) << "a leading '/' anchors at the top";
  EXPECT_TRUE(rules.ignored("docs/a.tmp", false));
  EXPECT_FALSE(rules.ignored("x/docs/a.tmp", false)) << "a pattern with a '/' is anchored";
  EXPECT_FALSE(rules.ignored("docs/sub/a.tmp", false)) << "'*' does not cross a '/'";
  EXPECT_TRUE(rules.ignored("x/y/z.log", false));
  EXPECT_FALSE(rules.ignored("x/keep.log", false)) << "the last matching line wins";
  EXPECT_TRUE(rules.ignored("locked/inside.cpp", false)) << "git never looks inside an ignored folder";
  EXPECT_TRUE(rules.ignored("a/b/deep.h", false));
  EXPECT_FALSE(IgnoreRules::parse("").ignored("anything", false));
}

}  // namespace
}  // namespace pt::grade
