// Named GPU presets (`--gpu NAME`): what a tile-based GPU does, as TilerConfig settings: its
// tile-size rule and tile buffer, framebuffer compression, transaction elimination and L2.
// Defaults stay ontile's own; a preset only changes what it names (docs/fidelity.md).
#pragma once
#include <string>
#include <vector>

#include "memory/transaction_elimination.h"
#include "tiler/render_pass_executor.h"

namespace ontile {

struct GpuPreset {
  std::string name;
  std::string description;  // the GPU, and where the figures come from
  TileSizeRule rule = TileSizeRule::Budget;
  int tile_size_px = 16;                 // the largest tile the rule picks
  int color_budget_bits_per_px = 128;    // Budget rule
  uint32_t tile_buffer_bytes = 0;        // Panfrost rule
  bool tile_buffer_pipelining_required = false;
  FreedrenoGmem gmem;                    // Freedreno rule
  bool afbc = false;
  bool transaction_elimination = false;
  CrcTargets crc_targets = CrcTargets::OnePerPass;  // which writes of a pass keep CRCs (the GPU's arch)
  // Index-driven vertex shading (TilerConfig::idvs: positions for every vertex, varyings only for
  // the vertices of triangles that survive culling): Mali Bifrost and later do it. Varying
  // precision and texture compression are not preset: they are the application's choices (its
  // shaders' mediump varyings, its assets' texture formats), given with --varying-precision and
  // --texture-compression.
  bool index_driven_vertex_shading = false;
  uint32_t l2_bytes = 0;  // 0: ontile's default caches; else the texture and parameter caches
};

const std::vector<GpuPreset>& gpu_presets();
// nullptr when no preset has that name.
const GpuPreset* find_gpu_preset(const std::string& name);
// The names, in table order; and comma separated, for messages.
std::vector<std::string> gpu_preset_list();
std::string gpu_preset_names();
// Sets what `preset` names in `config` (transaction elimination: a fresh CRC history).
void apply_gpu_preset(const GpuPreset& preset, TilerConfig& config);

}  // namespace ontile
