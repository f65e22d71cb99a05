// libFuzzer target: the .gltf (JSON) loader. The input is written as <scratch>/fuzz.gltf and
// loaded through load_gltf, the CLI's entry point. An ontile::Error is the expected outcome for
// a bad file; a crash, sanitizer report, leak, other exception, timeout or runaway memory is a
// finding (scripts/fuzz_smoke.sh, docs/robustness.md).
#include <cstddef>
#include <cstdint>

#include "fuzz_scratch.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path path = ontile::fuzz::write_scratch_file("fuzz.gltf", data, size);
  try {
    ontile::GltfLoadOptions options;
    // Keep going past NaN/Inf positions (the library's lenient mode) so the rest of the file
    // is decoded too; the CLI's default rejects them earlier, on a subset of this path.
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
