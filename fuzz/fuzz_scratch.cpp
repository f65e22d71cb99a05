// The fuzz targets' scratch folder (fuzz_scratch.h): the fuzzed file plus the external buffer
// and image that seeds reference by relative URI.
#include "fuzz_scratch.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "scene/gen/png_encoder.h"

namespace ontile::fuzz {
namespace {

void write_bytes(const std::filesystem::path& path, const void* data, size_t size) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!file) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
}

// Bytes 0-63: 16 floats (a triangle's three positions, then values read as a normal or as
// texture coordinates);
// 64-83: ten uint16 indices; 96-119: six uint32 indices; the rest zero. Seeds point accessors
// of several component types into it.
std::vector<uint8_t> external_buffer() {
  const float floats[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1};
  const uint16_t short_indices[] = {0, 1, 2, 2, 1, 0, 0, 2, 1, 0};
  const uint32_t int_indices[] = {0, 1, 2, 0, 2, 1};
  std::vector<uint8_t> bytes(256, 0);
  std::memcpy(bytes.data(), floats, sizeof(floats));
  std::memcpy(bytes.data() + 64, short_indices, sizeof(short_indices));
  std::memcpy(bytes.data() + 96, int_indices, sizeof(int_indices));
  return bytes;
}

void remove_scratch_folder() {
  std::error_code ignored;
  std::filesystem::remove_all(scratch_folder(), ignored);
}

std::filesystem::path make_scratch_folder() {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("ontile_fuzz_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const std::vector<uint8_t> buffer = external_buffer();
  write_bytes(folder / "buffer.bin", buffer.data(), buffer.size());
  gen::RgbImage image;
  image.width_px = 4;
  image.height_px = 4;
  image.rgb.resize(4 * 4 * 3);
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<uint8_t>(i * 5);
  const std::vector<uint8_t> png = gen::encode_png(image);
  write_bytes(folder / "texture.png", png.data(), png.size());
  return folder;
}

}  // namespace

const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = make_scratch_folder();
  static const bool cleanup_registered = std::atexit(remove_scratch_folder) == 0;
  (void)cleanup_registered;
  return folder;
}

std::filesystem::path write_scratch_file(const char* name, const uint8_t* data, size_t size) {
  const std::filesystem::path path = scratch_folder() / name;
  write_bytes(path, data, size);
  return path;
}

}  // namespace ontile::fuzz
