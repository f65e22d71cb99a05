// Tests for the output layer (util/atomic_file.h): outputs appear together or not at all,
// folders are never created, read-only files are refused and keep their mode, replaced files
// keep their mode, and temporaries are removed on errors and on SIGTERM / SIGINT.
#include "util/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <iterator>

#include "util/error.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;

class StagedOutputsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ontile_staged_outputs_" + std::to_string(getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_);
  }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  static std::string read(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  }
  static mode_t mode_of(const fs::path& p) {
    struct stat st;
    EXPECT_EQ(stat(p.c_str(), &st), 0) << p;
    return st.st_mode & 07777;
  }
  fs::path dir_;
};

TEST_F(StagedOutputsTest, NothingAppearsBeforeCommitAndAllAppearAtCommit) {
  StagedOutputs outputs;
  outputs.stage_text(dir_ / "a.json", "first");
  outputs.stage_text(dir_ / "b.csv", "second");
  EXPECT_FALSE(fs::exists(dir_ / "a.json"));
  EXPECT_FALSE(fs::exists(dir_ / "b.csv"));
  EXPECT_EQ(entries().size(), 2u);  // the two hidden temporaries
  outputs.commit();
  EXPECT_EQ(entries(), (std::vector<std::string>{"a.json", "b.csv"}));
  EXPECT_EQ(read(dir_ / "a.json"), "first");
  EXPECT_EQ(read(dir_ / "b.csv"), "second");
}

TEST_F(StagedOutputsTest, AFailingSecondOutputLeavesNeitherFileNorTemporary) {
  {
    StagedOutputs outputs;
    outputs.stage_text(dir_ / "image.png", "pixels");
    EXPECT_THROW(outputs.stage(dir_ / "report.json",
                               [](const fs::path& tmp) {
                                 std::ofstream(tmp) << "half";
                                 throw Error("report.json: disk full");
                               }),
                 Error);
  }  // destroyed without commit
  EXPECT_TRUE(entries().empty());
}

TEST_F(StagedOutputsTest, MissingFoldersAreNotCreated) {
  EXPECT_THROW(write_file_atomically(dir_ / "new" / "x.txt", [](const fs::path&) {}), Error);
  EXPECT_FALSE(fs::exists(dir_ / "new"));
  try {
    check_output_path(dir_ / "new" / "x.txt");
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((dir_ / "new" / "x.txt").string()), std::string::npos) << e.what();
  }
}

TEST_F(StagedOutputsTest, AReadOnlyTargetIsRefusedAndKeepsItsContentAndMode) {
  const fs::path target = dir_ / "keep.png";
  std::ofstream(target) << "original";
  chmod(target.c_str(), 0444);
  EXPECT_THROW(write_file_atomically(target, [](const fs::path& tmp) { std::ofstream(tmp) << "new"; }), Error);
  EXPECT_EQ(read(target), "original");
  EXPECT_EQ(mode_of(target), 0444u);
  EXPECT_EQ(entries(), std::vector<std::string>{"keep.png"});
}

TEST_F(StagedOutputsTest, AReplacedFileKeepsItsMode) {
  const fs::path target = dir_ / "shared.json";
  std::ofstream(target) << "old";
  chmod(target.c_str(), 0664);
  write_file_atomically(target, [](const fs::path& tmp) { std::ofstream(tmp) << "new"; });
  EXPECT_EQ(read(target), "new");
  EXPECT_EQ(mode_of(target), 0664u);
}

TEST_F(StagedOutputsTest, AFolderIsNotATarget) {
  fs::create_directory(dir_ / "taken.json");
  EXPECT_THROW(check_output_path(dir_ / "taken.json"), Error);
}

// The process is killed while a temporary exists: the handler removes it, then the signal's
// default action still ends the process (exit status "killed by SIGTERM").
void stage_and_die(const fs::path& target, int signal_number) {
  install_temporary_file_cleanup();
  StagedOutputs outputs;
  outputs.stage(target, [&](const fs::path& tmp) {
    std::ofstream(tmp) << "partial";
    std::raise(signal_number);
  });
}

TEST_F(StagedOutputsTest, TemporariesAreRemovedOnSigtermAndSigint) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(stage_and_die(dir_ / "killed.exr", SIGTERM), ::testing::KilledBySignal(SIGTERM), "");
  EXPECT_TRUE(entries().empty());
  EXPECT_EXIT(stage_and_die(dir_ / "interrupted.png", SIGINT), ::testing::KilledBySignal(SIGINT), "");
  EXPECT_TRUE(entries().empty());
}

}  // namespace
}  // namespace ontile
