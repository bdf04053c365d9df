// The report sends each failure to its handout section: every task of tasks/
// must have one, labelled by the handout's own heading (never a TODO tag).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <unistd.h>

#include "pt_source_dir.h"
#include "report/handout_index.h"

namespace pt::grade {
namespace {

namespace fs = std::filesystem;

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The task ids the stubs are tagged with (TODO(PnTm)), read from tasks/.
std::set<std::string> task_ids() {
  std::set<std::string> ids;
  const std::regex tag(R"(TODO\((P[0-9]+T[0-9]+)\))");
  for (const auto& e : fs::directory_iterator(fs::path(PT_SOURCE_DIR) / "tasks")) {
    const std::string text = text_of(e.path());
    for (std::sregex_iterator it(text.begin(), text.end(), tag), end; it != end; ++it) ids.insert((*it)[1].str());
  }
  return ids;
}

TEST(HandoutIndex, EveryTaskHasASectionLabelledByItsHeading) {
  // The stubs' tags are the list of tasks only where tasks/ holds the stubs:
  // in the student release tasks/ is the student's work, tags removed as
  // tasks are done.
  if (!fs::is_directory(fs::path(PT_SOURCE_DIR) / "reference"))
    GTEST_SKIP() << "tasks/ is the student's here: the stubs' tags are checked in the instructors' checkout";
  const HandoutIndex index = index_handouts((fs::path(PT_SOURCE_DIR) / "handouts").string());
  const std::set<std::string> ids = task_ids();
  ASSERT_GE(ids.size(), 16u) << "tasks/ should tag every task TODO(PnTm)";
  for (const std::string& id : ids) {
    auto it = index.tasks.find(id);
    ASSERT_NE(it, index.tasks.end()) << id << " has no handout section";
    const HandoutRef& ref = it->second;
    EXPECT_EQ(ref.file, "handouts/part" + id.substr(1, id.find('T') - 1) + ".md") << id;
    EXPECT_EQ(ref.section.find("TODO"), std::string::npos) << id << ": label \"" << ref.section << "\"";
    EXPECT_EQ(ref.section.find('`'), std::string::npos) << id << ": label \"" << ref.section << "\"";
    // The label is a heading of that handout, as written there (less a tag's markup).
    const std::string handout = text_of(fs::path(PT_SOURCE_DIR) / ref.file);
    const std::string heading_start = "\n## " + ref.section.substr(0, ref.section.find(' ') + 1);
    EXPECT_NE(handout.find(heading_start), std::string::npos) << id << ": \"" << ref.section << "\" is not a heading";
  }
}

TEST(HandoutIndex, ATodoTagInAHeadingReadsAsItsTaskId) {
  const fs::path dir = fs::temp_directory_path() / ("pt_handout_index_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "part5.md") << "# Part 5\n\n## 4. The task: `TODO(P5T1)`\n\ntext\n";
  const HandoutIndex index = index_handouts(dir.string());
  fs::remove_all(dir);
  ASSERT_EQ(index.tasks.count("P5T1"), 1u);
  EXPECT_EQ(index.tasks.at("P5T1").section, "4. The task: P5T1");
}

}  // namespace
}  // namespace pt::grade
