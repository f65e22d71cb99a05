// The CLI's outputs (README, "The CLI"): `--report -` goes to standard output alone, outputs go
// into existing folders only, a read-only target is refused unchanged, a run whose second output
// cannot be written leaves neither output nor temporary, identical runs write identical bytes,
// golden exits 1 for a mismatch and 2 for an unreadable reference, AOVs work with MSAA, and an
// IMR run prints no tiles.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "cli/cli_split_runner.h"
#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;

using ontile::test::run_cli_split;
using ontile::test::SplitRun;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

class CliOutputs : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    scratch_ = ontile::test::temp_folder("ontile_cli_outputs_" + name);
    dir_ = scratch_ / "outputs";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(scratch_); }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  SplitRun run(const std::string& args) { return run_cli_split(args, scratch_); }
  fs::path scratch_, dir_;
};

TEST_F(CliOutputs, ReportDashGoesToStandardOutputAlone) {
  const std::string cwd_dash = (fs::current_path() / "-").string();
  const bool dash_existed = fs::exists(cwd_dash);
  const SplitRun r = run("render --scene " + kDemo + " --size 64x36 --threads 2 --out " + (dir_ / "a.png").string() +
                         " --report -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{", 0), 0u) << r.out.substr(0, 200);
  EXPECT_NE(r.out.find("\"ontile-report\""), std::string::npos);
  EXPECT_EQ(r.out.find("external traffic"), std::string::npos) << "the summary belongs on stderr";
  EXPECT_NE(r.err.find("external traffic"), std::string::npos) << r.err;
  EXPECT_EQ(entries(), std::vector<std::string>{"a.png"});
  EXPECT_EQ(fs::exists(cwd_dash), dash_existed) << "a file named '-' was written";
}

TEST_F(CliOutputs, AMissingOutputFolderIsAnErrorAndNothingIsCreated) {
  const SplitRun r = run("render --scene " + kDemo + " --size 32x18 --out " + (dir_ / "new" / "sub" / "a.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_TRUE(entries().empty());
}

TEST_F(CliOutputs, AReadOnlyTargetIsRefusedAndKeepsItsBytesAndMode) {
  const fs::path target = dir_ / "keep.png";
  std::ofstream(target) << "not replaced";
  chmod(target.c_str(), 0444);
  const SplitRun r = run("render --scene " + kDemo + " --size 32x18 --out " + target.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("read-only"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(target), "not replaced");
  struct stat st;
  ASSERT_EQ(stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0444u);
  EXPECT_EQ(entries(), std::vector<std::string>{"keep.png"});
}

// The image could be written, the report cannot: neither appears, and no temporary remains.
TEST_F(CliOutputs, AFailingSecondOutputLeavesNoImageAndNoTemporary) {
  const fs::path report = dir_ / "locked.json";
  std::ofstream(report) << "{}";
  chmod(report.c_str(), 0444);
  const SplitRun r = run("render --scene " + kDemo + " --size 32x18 --out " + (dir_ / "a.png").string() +
                         " --report " + report.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(report.string()), std::string::npos) << r.err;
  EXPECT_EQ(entries(), std::vector<std::string>{"locked.json"});
  EXPECT_EQ(read_file(report), "{}");
}

TEST_F(CliOutputs, IdenticalRunsWriteIdenticalBytes) {
  for (const char* ext : {".png", ".exr"}) {
    std::string first, second;
    for (std::string* bytes : {&first, &second}) {
      const fs::path out = dir_ / (std::string("image") + ext);
      const SplitRun r = run("render --scene " + kDemo + " --size 48x27 --threads 2 --out " + out.string());
      ASSERT_EQ(r.exit_code, 0) << r.err;
      *bytes = read_file(out);
      // The EXR writer's timestamp has one-second resolution: make the two runs a second apart.
      if (bytes == &first) std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    }
    EXPECT_TRUE(first == second) << ext;
  }
}

// The golden verb against a folder of references: a changed reference is a mismatch (1), an
// unreadable one an input error (2).
TEST_F(CliOutputs, GoldenExitsOneForAMismatchAndTwoForAnUnreadableReference) {
  const fs::path golden = std::string(ONTILE_SOURCE_DIR) + "/golden";
  const fs::path changed = scratch_ / "changed", unreadable = scratch_ / "unreadable";
  fs::create_directories(changed);
  fs::create_directories(unreadable);
  for (const auto& e : fs::directory_iterator(golden)) {
    if (e.path().extension() != ".png") continue;
    fs::copy_file(e.path(), changed / e.path().filename());
    std::ofstream(unreadable / e.path().filename()) << "not a png";
  }
  // One demo case (the shared-asset cases are skipped here) gets another demo case's reference:
  // the same size, other pixels.
  const std::string first_png = "demo_lambert.png", other = "demo_cartoon.png";
  ASSERT_TRUE(fs::exists(changed / first_png) && fs::exists(changed / other));
  fs::copy_file(changed / other, changed / first_png, fs::copy_options::overwrite_existing);
  const std::string no_assets = " --assets " + (scratch_ / "no_assets").string();

  const SplitRun mismatch =
      run("golden --dir " + changed.string() + " --failures " + dir_.string() + no_assets);
  EXPECT_EQ(mismatch.exit_code, 1) << mismatch.out << mismatch.err;
  EXPECT_NE(mismatch.out.find("MISMATCH"), std::string::npos) << mismatch.out;
  EXPECT_EQ(mismatch.err.rfind("error: ", 0), 0u) << mismatch.err;

  const SplitRun io = run("golden --dir " + unreadable.string() + " --failures " + dir_.string() + no_assets);
  EXPECT_EQ(io.exit_code, 2) << io.out << io.err;
  EXPECT_NE(io.err.find(unreadable.string()), std::string::npos) << io.err;
}

// MSAA AOVs hold each pixel's sample 0; at 1 sample they are the plain AOV.
TEST_F(CliOutputs, AovWithMsaaRenders) {
  for (const char* aov : {"depth", "primitive_id", "normal"}) {
    const fs::path out = dir_ / (std::string(aov) + ".exr");
    const SplitRun r = run("render --scene " + kDemo + " --size 48x27 --threads 2 --aov " + aov +
                           " --set msaa=4 --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << aov << "\n" << r.err;
    EXPECT_NE(r.out.find("4 samples per pixel"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(out)) << aov;
  }
}

TEST_F(CliOutputs, ImmediateModePrintsNoTiles) {
  const SplitRun imr = run("render --scene " + kDemo + " --size 48x27 --arch imr --out " + (dir_ / "i.png").string());
  ASSERT_EQ(imr.exit_code, 0) << imr.err;
  EXPECT_EQ(imr.out.find(" tiles,"), std::string::npos) << imr.out;
  EXPECT_NE(imr.out.find("immediate mode"), std::string::npos) << imr.out;
  EXPECT_NE(imr.out.find("render-target cache"), std::string::npos) << imr.out;
  const SplitRun tbdr = run("render --scene " + kDemo + " --size 48x27 --out " + (dir_ / "t.png").string());
  ASSERT_EQ(tbdr.exit_code, 0) << tbdr.err;
  EXPECT_NE(tbdr.out.find(" tiles,"), std::string::npos) << tbdr.out;
}

// A scene whose buffer lies one folder up: refused by default (exit 2, one error line naming the
// URI), rendered with --allow-outside-files.
TEST_F(CliOutputs, FilesOutsideTheSceneFolderNeedAnExplicitFlag) {
  const fs::path scene_dir = scratch_ / "scene";
  fs::create_directories(scene_dir);
  // One triangle: 3 float3 positions (36 bytes), little-endian.
  const float positions[9] = {-1.0f, -1.0f, 0.0f, 1.0f, -1.0f, 0.0f, 0.0f, 1.0f, 0.0f};
  {
    std::ofstream bin(scratch_ / "triangle.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(positions), sizeof(positions));
  }
  {
    std::ofstream gltf(scene_dir / "triangle.gltf");
    gltf << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
         << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
         << R"("buffers":[{"uri":"../triangle.bin","byteLength":36}],)"
         << R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
         << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
         << R"("min":[-1,-1,0],"max":[1,1,0]}]})";
  }
  const std::string args = "render --scene " + (scene_dir / "triangle.gltf").string() +
                           " --size 32x32 --out " + (dir_ / "t.png").string();
  const SplitRun refused = run(args);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_EQ(refused.err.rfind("error: ", 0), 0u) << refused.err;
  EXPECT_NE(refused.err.find("../triangle.bin"), std::string::npos) << refused.err;
  EXPECT_TRUE(entries().empty());
  const SplitRun allowed = run(args + " --allow-outside-files");
  EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
  EXPECT_EQ(entries(), std::vector<std::string>{"t.png"});
}

}  // namespace
