// Tests for image IO: exact PNG and EXR round trips, sRGB encoding on write, channel expansion,
// and errors (bad extension, unwritable target, missing or corrupt input) that leave no files.
#include "io/image_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <fstream>
#include <iterator>
#include <chrono>
#include <string>
#include <thread>

#include "raster/pixel_format.h"
#include "util/error.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;

class ImageIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ontile_image_io_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  std::vector<char> file_bytes(const fs::path& path) const {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // Expects `f` to throw an Error that names `path`.
  template <typename F>
  void expect_error_naming(const fs::path& path, F f) {
    try {
      f();
      ADD_FAILURE() << "no Error thrown for " << path;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  }

  fs::path dir_;
};

std::vector<uint8_t> pattern_bytes(size_t count) {
  std::vector<uint8_t> bytes(count);
  uint32_t state = 99u;
  for (uint8_t& b : bytes) {
    state = state * 1664525u + 1013904223u;
    b = static_cast<uint8_t>(state >> 24);
  }
  bytes[0] = 0;
  bytes[1] = 255;
  return bytes;
}

TEST_F(ImageIoTest, PngRoundTripIsExact) {
  const std::vector<uint8_t> rgba = pattern_bytes(7 * 5 * 4);
  const fs::path path = dir_ / "pattern.png";
  write_png_rgba8(path, 7, 5, rgba);
  int width = 0, height = 0;
  EXPECT_EQ(read_png_rgba8(path, width, height), rgba);
  EXPECT_EQ(width, 7);
  EXPECT_EQ(height, 5);
  const ImageRGBA32F image = read_image(path);
  ASSERT_EQ(image.pixels.size(), rgba.size());
  for (size_t i = 0; i < rgba.size(); ++i) {
    ASSERT_EQ(float_to_unorm(image.pixels[i], 8), rgba[i]) << i;
  }
  EXPECT_EQ(entries(), std::vector<std::string>{"pattern.png"});
  // Same input, same bytes.
  write_png_rgba8(dir_ / "again.png", 7, 5, rgba);
  EXPECT_EQ(file_bytes(path), file_bytes(dir_ / "again.png"));
}

TEST_F(ImageIoTest, PngWriteEncodesSrgbOnRequest) {
  const ImageRGBA32F image{2, 1, {0.5f, 1.0f, 0.0f, 0.5f, 0.2f, 2.0f, -1.0f, 1.0f}};
  int width = 0, height = 0;
  write_image(dir_ / "srgb.png", image, true);
  EXPECT_EQ(read_png_rgba8(dir_ / "srgb.png", width, height),
            (std::vector<uint8_t>{188, 255, 0, 128, linear_to_srgb8(0.2f), 255, 0, 255}));
  write_image(dir_ / "unorm.PNG", image, false);
  EXPECT_EQ(read_png_rgba8(dir_ / "unorm.PNG", width, height),
            (std::vector<uint8_t>{128, 255, 0, 128, 51, 255, 0, 255}));
}

TEST_F(ImageIoTest, ExrRoundTripIsExact) {
  ImageRGBA32F image{3, 2, {}};
  const float values[] = {0.0f,     -0.0f,       1.0f,
                          -3.5f,    1e-8f,       65504.5f,
                          1e30f,    0.1f,        std::bit_cast<float>(0x00000123u),
                          123.456f, 2.0f / 3.0f, -1e-30f};
  for (int i = 0; i < 24; ++i) image.pixels.push_back(values[i % 12] * (1.0f + i));
  const fs::path path = dir_ / "linear.exr";
  write_image(path, image, true);  // the sRGB flag does not apply to EXR
  const ImageRGBA32F back = read_image(path);
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  ASSERT_EQ(back.pixels.size(), image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    EXPECT_EQ(std::bit_cast<uint32_t>(back.pixels[i]), std::bit_cast<uint32_t>(image.pixels[i]))
        << i;
  }
  write_image(dir_ / "again.exr", image, true);
  EXPECT_EQ(file_bytes(path), file_bytes(dir_ / "again.exr"));
}

TEST_F(ImageIoTest, ExrChannelsAndExpansionToRgba) {
  const fs::path depth = dir_ / "depth.exr";
  write_exr_channels(depth, 2, 1, {"Z"}, {0.25f, 7.0f});
  EXPECT_EQ(read_image(depth).pixels,
            (std::vector<float>{0.25f, 0.25f, 0.25f, 1.0f, 7.0f, 7.0f, 7.0f, 1.0f}));
  const fs::path gray_alpha = dir_ / "ya.exr";
  write_exr_channels(gray_alpha, 1, 1, {"Y", "A"}, {0.5f, 0.75f});
  EXPECT_EQ(read_image(gray_alpha).pixels, (std::vector<float>{0.5f, 0.5f, 0.5f, 0.75f}));
  const fs::path xyz = dir_ / "normal.exr";
  write_exr_channels(xyz, 1, 2, {"N.x", "N.y", "N.z"}, {1.0f, -2.0f, 3.0f, 4.0f, 5.0f, -6.0f});
  EXPECT_EQ(read_image(xyz).pixels,
            (std::vector<float>{1.0f, -2.0f, 3.0f, 1.0f, 4.0f, 5.0f, -6.0f, 1.0f}));
}

// Identical images give identical files: OpenImageIO would stamp EXRs with the current time
// (capDate), which has one-second resolution, so the second write comes more than a second later.
TEST_F(ImageIoTest, TheSameImageWrittenTwiceGivesTheSameBytes) {
  const ImageRGBA32F image{3, 2, {0.1f, 0.2f, 0.3f, 1.0f, 1.5f, -2.0f, 0.0f, 0.5f, 1, 1, 1, 1,
                                  0, 0, 0, 0, 0.25f, 0.5f, 0.75f, 1, 9, 8, 7, 6}};
  const std::vector<uint8_t> rgba = pattern_bytes(3 * 2 * 4);
  const auto write_all = [&](const std::string& suffix) {
    write_image(dir_ / ("image" + suffix + ".exr"), image, false);
    write_exr_channels(dir_ / ("aov" + suffix + ".exr"), 3, 2, {"Z"}, {1, 2, 3, 4, 5, 6});
    write_png_rgba8(dir_ / ("image" + suffix + ".png"), 3, 2, rgba);
  };
  write_all("1");
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write_all("2");
  for (const char* name : {"image%.exr", "aov%.exr", "image%.png"}) {
    std::string first = name, second = name;
    first.replace(first.find('%'), 1, "1");
    second.replace(second.find('%'), 1, "2");
    EXPECT_TRUE(file_bytes(dir_ / first) == file_bytes(dir_ / second)) << first << " and " << second << " differ";
  }
}

TEST_F(ImageIoTest, BadExtensionsAndSizesLeaveNoFile) {
  const ImageRGBA32F image{1, 1, {1.0f, 1.0f, 1.0f, 1.0f}};
  expect_error_naming(dir_ / "x.jpg", [&] { write_image(dir_ / "x.jpg", image, true); });
  expect_error_naming(dir_ / "noext", [&] { write_image(dir_ / "noext", image, true); });
  expect_error_naming(dir_ / "x.exr", [&] { write_png_rgba8(dir_ / "x.exr", 1, 1, {1, 2, 3, 4}); });
  expect_error_naming(dir_ / "x.png",
                      [&] { write_exr_channels(dir_ / "x.png", 1, 1, {"Z"}, {1}); });
  expect_error_naming(dir_ / "short.png", [&] {
    write_png_rgba8(dir_ / "short.png", 2, 1, {1, 2, 3, 4});
  });
  expect_error_naming(dir_ / "short.exr",
                      [&] { write_exr_channels(dir_ / "short.exr", 1, 1, {"Z"}, {}); });
  expect_error_naming(dir_ / "empty.exr",
                      [&] { write_image(dir_ / "empty.exr", ImageRGBA32F{}, true); });
  EXPECT_TRUE(entries().empty());
}

TEST_F(ImageIoTest, UnwritableTargetsLeaveNoFile) {
  const ImageRGBA32F image{1, 1, {1.0f, 1.0f, 1.0f, 1.0f}};
  const fs::path missing_folder = dir_ / "no_such_folder" / "out.png";
  expect_error_naming(missing_folder, [&] { write_image(missing_folder, image, true); });
  // A target that is a folder is refused before anything is written.
  fs::create_directory(dir_ / "taken.exr");
  expect_error_naming(dir_ / "taken.exr", [&] { write_image(dir_ / "taken.exr", image, true); });
  fs::create_directory(dir_ / "taken.png");
  expect_error_naming(dir_ / "taken.png", [&] { write_image(dir_ / "taken.png", image, true); });
  EXPECT_EQ(entries(), (std::vector<std::string>{"taken.exr", "taken.png"}));
  EXPECT_TRUE(fs::is_empty(dir_ / "taken.exr"));
}

TEST_F(ImageIoTest, MissingAndCorruptInputsNameTheFile) {
  int width = 0, height = 0;
  const fs::path missing = dir_ / "missing.png";
  expect_error_naming(missing, [&] { read_image(missing); });
  expect_error_naming(missing, [&] { read_png_rgba8(missing, width, height); });
  expect_error_naming(dir_, [&] { read_image(dir_); });

  const fs::path garbage = dir_ / "garbage.png";
  std::ofstream(garbage, std::ios::binary) << "this is not an image at all";
  expect_error_naming(garbage, [&] { read_image(garbage); });
  expect_error_naming(garbage, [&] { read_png_rgba8(garbage, width, height); });

  // A real PNG cut in half: the header parses, the pixel data does not.
  const fs::path full = dir_ / "full.png";
  write_png_rgba8(full, 64, 64, pattern_bytes(64 * 64 * 4));
  const std::vector<char> bytes = file_bytes(full);
  const fs::path truncated = dir_ / "truncated.png";
  std::ofstream(truncated, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 2));
  expect_error_naming(truncated, [&] { read_image(truncated); });
  expect_error_naming(truncated, [&] { read_png_rgba8(truncated, width, height); });

  const fs::path exr = dir_ / "image.exr";
  write_exr_channels(exr, 1, 1, {"Z"}, {1.0f});
  expect_error_naming(exr, [&] { read_png_rgba8(exr, width, height); });
}

}  // namespace
}  // namespace ontile
