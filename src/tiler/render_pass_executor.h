// Executes a render pass the way a tile-based GPU does: validate, pick the tile size that fits
// the tile-memory colour budget, bin all geometry, then run every tile in parallel (oneTBB)
// and count the external memory traffic.
#pragma once
#include <memory>

#include "memory/memory_model.h"
#include "tiler/pass_report.h"
#include "tiler/render_pass.h"
#include "tiler/tile_size_rules.h"

namespace ontile {

enum class Architecture { Tbdr, Imr };
enum class VaryingPrecision { Fp32, Fp16 };

struct TilerConfig {
  Architecture architecture = Architecture::Tbdr;
  int tile_size_px = 16;                 // Mali's 16x16 by default
  int color_budget_bits_per_px = 128;    // tile-buffer colour bits per pixel (Mali-G76: 128)
  // How each pass's tile size is chosen (tile_size_rules.h): the budget rule above (default), or
  // a driver's rule with its constants (the --gpu presets, tiler/gpu_presets.h).
  TileSizeRule tile_size_rule = TileSizeRule::Budget;
  uint32_t tile_buffer_bytes = 0;           // Panfrost: the optimal tile-buffer bytes
  bool tile_buffer_pipelining_required = false;  // Panfrost on v6 (Mali-G71)
  FreedrenoGmem gmem;                       // Freedreno
  // Vertex snapping precision: 8 (D3D11 3.2.4.1, 16.8 fixed point) or 4 (Vulkan's minimum
  // subPixelPrecisionBits); anything else makes execute_render_pass throw.
  int subpixel_bits = kSubpixelBits;
  TextureCacheConfig texture_cache;
  ParameterCacheConfig parameter_cache;         // TBDR only; off by default
  RenderTargetCacheConfig render_target_cache;  // IMR only
  // Skip 8x8 cells that hierarchical Z proves occluded (tiler/hierarchical_depth.h). Changes no
  // image bit and no traffic count, only time and the cells_hiz_rejected counter; off is for
  // measuring what it saves.
  bool hierarchical_z = true;
  // Arm Frame Buffer Compression (memory/afbc.h): single-sample colour attachments of up to 32
  // bits per pixel are loaded, stored and resolved at their compressed size. TBDR only.
  bool afbc = false;
  // Transaction elimination (memory/transaction_elimination.h): the CRC history that frames
  // rendered with this config share (a tile write equal to the previous frame's is skipped);
  // null: off. Needs 16x16 tiles (the CLI refuses other sizes). TBDR only.
  std::shared_ptr<TileSignatureHistory> transaction_elimination;
  // Index-driven vertex shading (Mali Bifrost/Valhall): the parameter buffer holds varyings only
  // for vertices of triangles that survive culling; positions for every vertex. TBDR only.
  bool idvs = false;
  // Bytes per stored varying component: fp32 (4, as before) or fp16 (2). Prices storage only:
  // varyings are still interpolated in fp32, so images do not change.
  VaryingPrecision varying_precision = VaryingPrecision::Fp32;
};

// The memory model's configuration out of the tiler's.
MemoryConfig memory_config_of(const TilerConfig& config);

// Runs on the calling thread's oneTBB arena (callers pick the thread count with a
// tbb::task_arena). `memory` is the frame's external memory (make_memory_model(
// memory_config_of(config))): it prices what the pass moves and carries the texture cache from
// pass to pass within a frame. Images are the same for every memory model; only the traffic
// differs. Throws ontile::Error when the pass is invalid.
PassReport execute_render_pass(const RenderPassDesc& pass, const TilerConfig& config,
                               MemoryModel& memory);

// What the memory model sees of `pass` at the given tile size.
PassMemoryDesc describe_pass_memory(const RenderPassDesc& pass, int tile_width_px, int tile_height_px);

// The tile size used for a pass needing `color_bits_per_px` of tile memory: the configured
// square tile, its area halved (height first) until the colour attachments fit the budget
// (as panfrost's tile-size selection does for Mali).
void select_tile_size(const TilerConfig& config, int color_bits_per_px, int& tile_width_px,
                      int& tile_height_px);
// The tile size config.tile_size_rule picks for `pass`.
TileSize pass_tile_size(const TilerConfig& config, const RenderPassDesc& pass);

}  // namespace ontile
