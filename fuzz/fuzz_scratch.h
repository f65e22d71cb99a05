// Fuzz-target helper: a per-process scratch folder holding the fuzzed file and the few
// external files the seed corpus refers to, so the loaders read inputs through their real
// file-based entry point (load_gltf takes a path, as the CLI does).
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace ontile::fuzz {

// <TMPDIR>/ontile_fuzz_<pid>, created on the first call with `buffer.bin` (256 bytes: floats
// and indices a seed's external buffer can point at) and `texture.png` (a 4x4 RGB image);
// removed when the process exits normally.
const std::filesystem::path& scratch_folder();

// Writes `size` bytes to scratch_folder()/name (replacing it) and returns the path.
std::filesystem::path write_scratch_file(const char* name, const uint8_t* data, size_t size);

}  // namespace ontile::fuzz
