// Test helper: builds small glTF files (JSON with base64 data URIs, external .bin, or GLB) and
// uncompressed PNGs in a per-test temporary folder, for the glTF loader tests.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile::test {

inline constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
                     kUnsignedInt = 5125, kFloat = 5126;

// Per process (ctest may run tests in parallel processes); removed when the tests end.
inline std::filesystem::path gltf_test_root() {
  return std::filesystem::temp_directory_path() / ("ontile_gltf_" + std::to_string(getpid()));
}

class RemoveGltfTestRoot : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(gltf_test_root(), ignored);
  }
};
inline ::testing::Environment* const kRemoveGltfTestRoot =
    ::testing::AddGlobalTestEnvironment(new RemoveGltfTestRoot);

// A fresh folder per test.
inline std::filesystem::path gltf_test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      gltf_test_root() / (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream file(path, std::ios::binary);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(file.good()) << path;
}

inline std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                   b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(triple >> 18) & 63];
    out += kAlphabet[(triple >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(triple >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[triple & 63] : '=';
  }
  return out;
}

template <typename T>
std::vector<uint8_t> as_bytes(const std::vector<T>& values) {
  std::vector<uint8_t> bytes(values.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

// An uncompressed PNG (zlib "stored" blocks), so tests can make images of any channel count
// and bit depth without an encoder. color_type: 0 grey, 2 RGB, 4 grey+alpha, 6 RGBA.
// `samples` holds one value per channel per pixel, row-major; 16-bit samples are big-endian
// in the file as PNG requires.
inline std::vector<uint8_t> make_png(int width, int height, int color_type, int bit_depth,
                                     const std::vector<uint16_t>& samples) {
  const int channels = color_type == 0 ? 1 : color_type == 2 ? 3 : color_type == 4 ? 2 : 4;
  const size_t bytes_per_sample = bit_depth == 16 ? 2 : 1;
  std::vector<uint8_t> raw;
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);  // filter type None
    for (int i = 0; i < width * channels; ++i) {
      const uint16_t s = samples[static_cast<size_t>(y * width * channels + i)];
      if (bytes_per_sample == 2) raw.push_back(static_cast<uint8_t>(s >> 8));
      raw.push_back(static_cast<uint8_t>(s & 0xFF));
    }
  }
  std::vector<uint8_t> zlib = {0x78, 0x01};
  for (size_t offset = 0; offset < raw.size() || offset == 0; offset += 65535) {
    const size_t length = std::min<size_t>(65535, raw.size() - offset);
    zlib.push_back(offset + length >= raw.size() ? 1 : 0);
    zlib.push_back(static_cast<uint8_t>(length & 0xFF));
    zlib.push_back(static_cast<uint8_t>(length >> 8));
    zlib.push_back(static_cast<uint8_t>(~length & 0xFF));
    zlib.push_back(static_cast<uint8_t>((~length >> 8) & 0xFF));
    zlib.insert(zlib.end(), raw.begin() + static_cast<std::ptrdiff_t>(offset),
                raw.begin() + static_cast<std::ptrdiff_t>(offset + length));
    if (raw.empty()) break;
  }
  uint32_t a = 1, b = 0;
  for (uint8_t byte : raw) {
    a = (a + byte) % 65521;
    b = (b + a) % 65521;
  }
  const uint32_t adler = (b << 16) | a;
  for (int shift = 24; shift >= 0; shift -= 8) zlib.push_back(static_cast<uint8_t>(adler >> shift));

  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  auto put32 = [](std::vector<uint8_t>& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(v >> shift));
  };
  auto chunk = [&](const char* type, const std::vector<uint8_t>& data) {
    put32(png, static_cast<uint32_t>(data.size()));
    std::vector<uint8_t> typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    uint32_t crc = 0xFFFFFFFFu;
    for (uint8_t byte : typed) {
      crc ^= byte;
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    png.insert(png.end(), typed.begin(), typed.end());
    put32(png, crc ^ 0xFFFFFFFFu);
  };
  std::vector<uint8_t> header;
  put32(header, static_cast<uint32_t>(width));
  put32(header, static_cast<uint32_t>(height));
  header.insert(header.end(),
                {static_cast<uint8_t>(bit_depth), static_cast<uint8_t>(color_type), 0, 0, 0});
  chunk("IHDR", header);
  chunk("IDAT", zlib);
  chunk("IEND", {});
  return png;
}

// Collects binary data into one buffer and records bufferViews and accessors in `json`.
class GltfBuilder {
 public:
  nlohmann::json json = {{"asset", {{"version", "2.0"}}}};
  std::vector<uint8_t> bin;

  // Appends bytes (4-byte aligned) as a new bufferView; returns its index.
  int add_view(const std::vector<uint8_t>& bytes, size_t byte_stride = 0) {
    while (bin.size() % 4 != 0) bin.push_back(0xEE);
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}};
    if (byte_stride != 0) view["byteStride"] = byte_stride;
    bin.insert(bin.end(), bytes.begin(), bytes.end());
    json["bufferViews"].push_back(view);
    return static_cast<int>(json["bufferViews"].size()) - 1;
  }
  int add_accessor(nlohmann::json accessor) {
    json["accessors"].push_back(std::move(accessor));
    return static_cast<int>(json["accessors"].size()) - 1;
  }
  // A tightly packed accessor over its own bufferView.
  template <typename T>
  int add_data(const std::vector<T>& values, int component_type, const std::string& type,
               size_t count, bool normalized = false) {
    const int view = add_view(as_bytes(values));
    return add_accessor({{"bufferView", view},
                         {"componentType", component_type},
                         {"type", type},
                         {"count", count},
                         {"normalized", normalized}});
  }
  int add_positions(const std::vector<float>& xyz) {
    return add_data(xyz, kFloat, "VEC3", xyz.size() / 3);
  }
  int add_mesh(nlohmann::json primitives) {
    json["meshes"].push_back({{"primitives", std::move(primitives)}});
    return static_cast<int>(json["meshes"].size()) - 1;
  }
  int add_node(nlohmann::json node) {
    json["nodes"].push_back(std::move(node));
    return static_cast<int>(json["nodes"].size()) - 1;
  }

  // Writes DIR/NAME.gltf; the buffer is a base64 data URI unless bin_name is given, then an
  // external file DIR/bin_name (not written when write_bin is false).
  std::filesystem::path write(const std::filesystem::path& dir, const std::string& name,
                              const std::string& bin_name = {}, bool write_bin = true) {
    finish_buffer(bin_name.empty() ? "data:application/octet-stream;base64," + base64(bin)
                                   : bin_name);
    if (!bin_name.empty() && write_bin) {
      write_bytes(dir / bin_name, std::string(bin.begin(), bin.end()));
    }
    const auto path = dir / (name + ".gltf");
    write_bytes(path, json.dump(2));
    return path;
  }

  // Writes DIR/NAME.glb: 12-byte header, JSON chunk, BIN chunk (GLB spec, section 4.4).
  std::filesystem::path write_glb(const std::filesystem::path& dir, const std::string& name) {
    finish_buffer({});
    std::string text = json.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::vector<uint8_t> chunk_bin = bin;
    while (chunk_bin.size() % 4 != 0) chunk_bin.push_back(0);
    std::string out = "glTF";
    auto put32 = [&out](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    put32(2);
    put32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + chunk_bin.size()));
    put32(static_cast<uint32_t>(text.size()));
    put32(0x4E4F534Au);  // "JSON"
    out += text;
    put32(static_cast<uint32_t>(chunk_bin.size()));
    put32(0x004E4942u);  // "BIN\0"
    out.append(chunk_bin.begin(), chunk_bin.end());
    const auto path = dir / (name + ".glb");
    write_bytes(path, out);
    return path;
  }

 private:
  void finish_buffer(const std::string& uri) {
    json["buffers"] = nlohmann::json::array();
    nlohmann::json buffer = {{"byteLength", bin.size()}};
    if (!uri.empty()) buffer["uri"] = uri;
    json["buffers"].push_back(buffer);
  }
};

// Loading `path` throws one ontile::Error: a single line that starts with the file's path and
// contains `phrase`.
inline void expect_load_error(const std::filesystem::path& path, const std::string& phrase,
                       const GltfLoadOptions& options = {}) {
  try {
    load_gltf(path, options);
    ADD_FAILURE() << "no error for " << path << " (expected '" << phrase << "')";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(phrase), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace ontile::test
