// The GPU presets (see gpu_presets.h). Sources: Arm's Mali-G76 figures (16x16 tiles, 128 bits
// per pixel of colour in the tile buffer, AFBC, transaction elimination, IDVS) as the issue and
// ../shared/REFERENCES.md give them; Mesa's drivers for the tile-size rules (tile_size_rules.h).
#include "tiler/gpu_presets.h"

#include "memory/transaction_elimination.h"

namespace ontile {
namespace {

constexpr uint32_t kKiB = 1024;

std::vector<GpuPreset> make_presets() {
  std::vector<GpuPreset> presets;
  GpuPreset g76;
  g76.name = "mali-g76";
  g76.description = "Arm Mali-G76 (Vulkan-Samples' subpasses, msaa and afbc device): 16x16 tiles, 128 bpp of colour "
                    "on tile, AFBC, transaction elimination (one CRC render target per pass, Bifrost v7), IDVS, "
                    "512 KiB L2";
  g76.afbc = true;
  g76.transaction_elimination = true;
  g76.index_driven_vertex_shading = true;
  g76.l2_bytes = 512 * kKiB;
  presets.push_back(g76);

  GpuPreset g71 = g76;
  g71.name = "mali-g71";
  g71.description = "Arm Mali-G71 (Vulkan-Samples' render_passes device): as mali-g76 (Bifrost: 16x16 tiles, 128 bpp, "
                    "AFBC, IDVS), but transaction elimination only in passes with one colour target (Bifrost v6); its "
                    "L2 (128 KiB-2 MiB by configuration) taken as 512 KiB";
  g71.crc_targets = CrcTargets::SingleTargetPasses;
  presets.push_back(g71);

  GpuPreset panfrost;
  panfrost.name = "panfrost";
  panfrost.description = "panfrost's tile-size rule for Mali-G76 (pan_select_tile_size, 8 KiB optimal tile buffer = "
                         "16 KiB / 2 with pipelining), nothing else changed";
  panfrost.rule = TileSizeRule::Panfrost;
  panfrost.tile_buffer_bytes = 16 * kKiB / 2;
  presets.push_back(panfrost);

  GpuPreset g13;
  g13.name = "apple-g13";
  g13.description = "Apple G13 (M1) as asahi sizes its tiles (agx_select_tile_size): 32x32, 32x16 or 16x16 within "
                    "32 KiB of colour per tile";
  g13.rule = TileSizeRule::Asahi;
  g13.tile_size_px = 32;
  presets.push_back(g13);

  GpuPreset a630;
  a630.name = "adreno-630";
  a630.description = "Qualcomm Adreno 630 as freedreno bins it (calc_nbins, layout_gmem): 1 MiB of GMEM holding "
                     "colour and depth, bins aligned to 32x16";
  a630.rule = TileSizeRule::Freedreno;
  presets.push_back(a630);
  return presets;
}

}  // namespace

const std::vector<GpuPreset>& gpu_presets() {
  static const std::vector<GpuPreset> presets = make_presets();
  return presets;
}

const GpuPreset* find_gpu_preset(const std::string& name) {
  for (const GpuPreset& p : gpu_presets()) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

std::vector<std::string> gpu_preset_list() {
  std::vector<std::string> names;
  for (const GpuPreset& p : gpu_presets()) names.push_back(p.name);
  return names;
}

std::string gpu_preset_names() {
  std::string names;
  for (const GpuPreset& p : gpu_presets()) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

void apply_gpu_preset(const GpuPreset& preset, TilerConfig& config) {
  config.tile_size_rule = preset.rule;
  config.tile_size_px = preset.tile_size_px;
  config.color_budget_bits_per_px = preset.color_budget_bits_per_px;
  config.tile_buffer_bytes = preset.tile_buffer_bytes;
  config.tile_buffer_pipelining_required = preset.tile_buffer_pipelining_required;
  config.gmem = preset.gmem;
  config.afbc = preset.afbc;
  config.transaction_elimination =
      preset.transaction_elimination ? std::make_shared<TileSignatureHistory>(preset.crc_targets) : nullptr;
  config.idvs = preset.index_driven_vertex_shading;
  if (preset.l2_bytes > 0) {
    config.texture_cache.size_bytes = preset.l2_bytes;
    config.parameter_cache.size_bytes = preset.l2_bytes;
  }
}

}  // namespace ontile
