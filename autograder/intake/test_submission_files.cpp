// Which files pt-grade submission takes from a folder or a zip, and what it refuses.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "intake/submission_files.h"

namespace pt::grade {
namespace {

namespace fs = std::filesystem;

const std::map<int, std::string> kExpected = {{1, "part1_raygen_intersect.cpp"}, {2, "part2_bvh.cpp"},
                                              {3, "part3_direct_lighting.cpp"}};

class SubmissionFiles : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pt-submission-files-" + std::to_string(::getpid()) + "-" +
                                        testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "in");
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& rel, const std::string& text) {
    fs::path p = dir_ / "in" / rel;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
  }
  // Zips the folder `in` with Debian's zip (the way students make them).
  std::string zip(const std::string& name = "sub.zip") {
    const std::string out = (dir_ / name).string();
    const std::string cmd = "cd '" + (dir_ / "in").string() + "' && zip -qry '" + out + "' . > /dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0) ADD_FAILURE() << "zip failed (Debian package zip)";
    return out;
  }
  std::string in() const { return (dir_ / "in").string(); }
  fs::path dir_;
};

std::string problems(const Submission& s) {
  std::string t;
  for (const auto& p : s.problems) t += p + "\n";
  return t;
}

TEST_F(SubmissionFiles, TaskFilesAtTheTopOrInTasksFromAFolderOrAZip) {
  write("part1_raygen_intersect.cpp", "// one");
  write("tasks/part3_direct_lighting.cpp", "// three");
  for (const std::string& path : {in(), zip()}) {
    Submission s = read_submission(path, kExpected);
    ASSERT_TRUE(s.problems.empty()) << path << "\n" << problems(s);
    ASSERT_EQ(s.files.size(), 2u) << path;
    EXPECT_EQ(s.files[0].part, 1);
    EXPECT_EQ(s.files[0].text, "// one");
    EXPECT_EQ(s.files[1].part, 3);
    EXPECT_EQ(s.files[1].where, "tasks/part3_direct_lighting.cpp");
  }
}

TEST_F(SubmissionFiles, OneEnclosingFolderAndOsMetadataAreLookedThrough) {
  write("my_work/tasks/part2_bvh.cpp", "// two");
  write("my_work/.DS_Store", "junk");
  write("__MACOSX/my_work/._part2_bvh.cpp", "junk");
  Submission s = read_submission(zip(), kExpected);
  ASSERT_TRUE(s.problems.empty()) << problems(s);
  ASSERT_EQ(s.files.size(), 1u);
  EXPECT_EQ(s.files[0].part, 2);
  EXPECT_EQ(s.notes.size(), 2u);
}

TEST_F(SubmissionFiles, AnyOtherFileRejectsTheSubmissionNamingIt) {
  write("part1_raygen_intersect.cpp", "// one");
  write("notes.txt", "hello");
  write("reference/part1_raygen_intersect.cpp", "// not a task file place");
  for (const std::string& path : {in(), zip()}) {
    Submission s = read_submission(path, kExpected);
    ASSERT_FALSE(s.problems.empty()) << path;
    EXPECT_NE(problems(s).find("notes.txt"), std::string::npos) << problems(s);
    EXPECT_NE(problems(s).find("reference/part1_raygen_intersect.cpp"), std::string::npos) << problems(s);
  }
}

TEST_F(SubmissionFiles, AFileOverTheLimitIsMarkedAndNotKept) {
  write("part1_raygen_intersect.cpp", std::string(kMaxTaskFileBytes + 1, 'x'));
  write("part2_bvh.cpp", std::string(kMaxTaskFileBytes, 'x'));
  for (const std::string& path : {in(), zip()}) {
    Submission s = read_submission(path, kExpected);
    ASSERT_TRUE(s.problems.empty()) << problems(s);
    ASSERT_EQ(s.files.size(), 2u);
    EXPECT_TRUE(s.files[0].too_large);
    EXPECT_TRUE(s.files[0].text.empty());
    EXPECT_FALSE(s.files[1].too_large);
  }
}

TEST_F(SubmissionFiles, AZipBombCostsOnlyTheLimit) {
  // 200 MB of zeros compress to about 200 KB; reading stops after 1 MiB.
  {
    std::ofstream out(dir_ / "in" / "part1_raygen_intersect.cpp", std::ios::binary);
    std::string block(1 << 20, '\0');
    for (int i = 0; i < 200; ++i) out << block;
  }
  const std::string z = zip();
  fs::remove(dir_ / "in" / "part1_raygen_intersect.cpp");
  Submission s = read_submission(z, kExpected);
  ASSERT_EQ(s.files.size(), 1u) << problems(s);
  EXPECT_TRUE(s.files[0].too_large);
}

TEST_F(SubmissionFiles, LinksTwiceSubmittedPartsAndBrokenZipsAreProblems) {
  write("part1_raygen_intersect.cpp", "// one");
  write("tasks/part1_raygen_intersect.cpp", "// one again");
  Submission twice = read_submission(in(), kExpected);
  EXPECT_NE(problems(twice).find("twice"), std::string::npos) << problems(twice);

  fs::remove_all(dir_ / "in");
  fs::create_directories(dir_ / "in");
  fs::create_symlink("/etc/passwd", dir_ / "in" / "part2_bvh.cpp");
  Submission link = read_submission(in(), kExpected);
  EXPECT_NE(problems(link).find("not a regular file"), std::string::npos) << problems(link);

  std::ofstream(dir_ / "broken.zip") << "PK\x03\x04 not really a zip";
  Submission broken = read_submission((dir_ / "broken.zip").string(), kExpected);
  EXPECT_FALSE(broken.problems.empty());

  Submission missing = read_submission((dir_ / "nothing-here").string(), kExpected);
  EXPECT_FALSE(missing.problems.empty());

  fs::remove_all(dir_ / "in");
  fs::create_directories(dir_ / "in");
  Submission empty = read_submission(in(), kExpected);
  EXPECT_NE(problems(empty).find("no task file"), std::string::npos) << problems(empty);
}

}  // namespace
}  // namespace pt::grade
