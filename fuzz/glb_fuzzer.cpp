// libFuzzer target: the .glb (binary glTF) loader. The input, its first four bytes replaced by
// the GLB magic "glTF" so every run takes the binary path, is written as <scratch>/fuzz.glb and
// loaded through load_gltf, the CLI's entry point. An ontile::Error is the expected outcome
// for a bad file; anything else is a finding (scripts/fuzz_smoke.sh, docs/robustness.md).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_scratch.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 4) return 0;
  std::vector<uint8_t> bytes(data, data + size);
  std::memcpy(bytes.data(), "glTF", 4);
  const std::filesystem::path path =
      ontile::fuzz::write_scratch_file("fuzz.glb", bytes.data(), bytes.size());
  try {
    // Lenient about NaN/Inf positions so the rest of the file is decoded too (see
    // gltf_fuzzer.cpp).
    ontile::GltfLoadOptions options;
    options.reject_non_finite_positions = false;
    ontile::GltfLoadStats stats;
    const ontile::Scene scene = ontile::load_gltf(path, options, &stats);
    (void)scene.drawn_triangle_count();
    (void)ontile::default_camera(scene);
  } catch (const ontile::Error&) {
    // A rejected file: the contract for bad input.
  }
  return 0;
}
