// Render pass execution (see render_pass_executor.h).
#include "tiler/render_pass_executor.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>

#include <tbb/combinable.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include "memory/granule_buffer_pool.h"
#include "raster/sample_pattern.h"
#include "raster/texture.h"
#include "tiler/detail/parameter_buffer.h"
#include "tiler/detail/parameter_reads.h"
#include "tiler/detail/tile_executor.h"
#include "util/error.h"
#include "util/parallel_for.h"

namespace ontile {
namespace {

[[noreturn]] void invalid(const RenderPassDesc& pass, const std::string& what) {
  throw Error("render pass '" + pass.name + "': " + what);
}

void validate(const RenderPassDesc& pass) {
  if (pass.width_px <= 0 || pass.height_px <= 0 || pass.width_px > kMaxTargetSizePx ||
      pass.height_px > kMaxTargetSizePx) {
    invalid(pass, "size " + std::to_string(pass.width_px) + "x" + std::to_string(pass.height_px) +
                      " outside 1.." + std::to_string(kMaxTargetSizePx));
  }
  if (!standard_sample_pattern(pass.samples)) {
    invalid(pass, "sample count " + std::to_string(pass.samples) + " is not 1, 2, 4 or 8");
  }
  int color_count = 0;
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentDesc& d = pass.attachments[a];
    const bool is_depth_slot = static_cast<int>(a) == pass.depth_index;
    if (is_depth_slot != is_depth_format(d.format)) {
      invalid(pass, "attachment '" + d.name + "' format " + format_name(d.format) +
                        (is_depth_slot ? " is not a depth format" : " is a depth format but not the depth attachment"));
    }
    if (!is_depth_slot) ++color_count;
    for (const Surface* s : {d.surface, d.resolve_surface}) {
      if (!s) continue;
      const int want_samples = s == d.surface ? pass.samples : 1;
      if (s->width() != pass.width_px || s->height() != pass.height_px) {
        invalid(pass, "attachment '" + d.name + "' surface is " + std::to_string(s->width()) +
                          "x" + std::to_string(s->height()) + ", the pass is " +
                          std::to_string(pass.width_px) + "x" + std::to_string(pass.height_px));
      }
      if (s->samples() != want_samples) {
        invalid(pass, "attachment '" + d.name + "' surface has " + std::to_string(s->samples()) +
                          " samples, expected " + std::to_string(want_samples));
      }
      if (s->format() != d.format) {
        invalid(pass, "attachment '" + d.name + "' surface format " + format_name(s->format()) +
                          " differs from the attachment's " + format_name(d.format));
      }
    }
    if (d.load == LoadAction::Load && !d.surface) {
      invalid(pass, "attachment '" + d.name + "' is transient but its load action is Load");
    }
    const bool resolves = d.store == StoreAction::Resolve || d.store == StoreAction::StoreAndResolve;
    if (resolves && !d.resolve_surface) {
      invalid(pass, "attachment '" + d.name + "' resolves but has no resolve surface");
    }
    if (resolves && is_depth_slot) invalid(pass, "depth attachment '" + d.name + "' cannot resolve");
  }
  if (color_count > kMaxColorTargets) {
    invalid(pass, std::to_string(color_count) + " colour attachments (at most " +
                      std::to_string(kMaxColorTargets) + ")");
  }
  if (pass.depth_index >= static_cast<int>(pass.attachments.size())) {
    invalid(pass, "depth attachment index out of range");
  }
  // What the tile holds at the start of a subpass: loaded attachments and whatever earlier
  // subpasses wrote (Vulkan 8.1: an input attachment must have defined contents).
  const int attachment_count = static_cast<int>(pass.attachments.size());
  std::vector<bool> defined(pass.attachments.size(), false);
  for (int a = 0; a < attachment_count; ++a) {
    defined[a] = pass.attachments[a].load != LoadAction::DontCare;
  }
  for (size_t s = 0; s < pass.subpasses.size(); ++s) {
    const SubpassDesc& sub = pass.subpasses[s];
    const std::string where = "subpass " + std::to_string(s);
    if (sub.color_outputs.size() > static_cast<size_t>(kMaxColorTargets)) {
      invalid(pass, where + " has " + std::to_string(sub.color_outputs.size()) +
                        " colour outputs (at most " + std::to_string(kMaxColorTargets) + ")");
    }
    for (int a : sub.color_outputs) {
      if (a < 0 || a >= attachment_count || a == pass.depth_index) {
        invalid(pass, where + " writes invalid attachment " + std::to_string(a));
      }
    }
    for (int a : sub.inputs) {
      if (a < 0 || a >= attachment_count) {
        invalid(pass, where + " reads invalid attachment " + std::to_string(a));
      }
      const std::string& name = pass.attachments[a].name;
      if (std::find(sub.color_outputs.begin(), sub.color_outputs.end(), a) != sub.color_outputs.end()) {
        invalid(pass, where + " writes its input attachment '" + name + "'");
      }
      if (a == pass.depth_index && !sub.depth_read_only && !sub.draws.empty()) {
        invalid(pass, where + " reads depth '" + name + "' as an input but does not declare depth read-only");
      }
      if (!defined[a]) {
        invalid(pass, where + " reads '" + name + "', which no earlier subpass wrote and which is not loaded or cleared");
      }
    }
    for (int a : sub.color_outputs) defined[a] = true;
    if (pass.depth_index >= 0 && !sub.depth_read_only) {
      for (const DrawCall& d : sub.draws) {
        if (d.raster.depth_write) defined[pass.depth_index] = true;
      }
    }
    for (const DrawCall& d : pass.subpasses[s].draws) {
      if (!d.vertex_shader) invalid(pass, "draw in subpass " + std::to_string(s) + " has no vertex shader");
    }
  }
}

int color_bits_per_pixel(const RenderPassDesc& pass) {
  int bits = 0;
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    if (static_cast<int>(a) != pass.depth_index) {
      bits += bits_per_pixel(pass.attachments[a].format) * pass.samples;
    }
  }
  return bits;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

SurfaceBytes bytes_of(const Surface* s) {
  if (!s) return {};
  return SurfaceBytes{s->format(), s->width(), s->height(), s->samples(), s->pixel_bytes(0, 0),
                      static_cast<size_t>(s->width()) * s->samples() * bytes_per_pixel(s->format())};
}

// The tile's own counters, and its primitive list, into its statistics.
void record_tile_counters(const TileCounters& c, const ParameterBuffer& params, int tile,
                          TileStats& stats) {
  stats.triangles = params.tile_offsets[tile + 1] - params.tile_offsets[tile];
  stats.fragments_shaded = c.fragments_shaded;
  stats.fragments_depth_rejected = c.fragments_depth_rejected;
  stats.cells_rasterized = c.cells_rasterized;
  stats.cells_hiz_rejected = c.cells_hiz_rejected;
  stats.parameter_bytes_read = c.parameter_bytes_read;
}

// Texture misses per tile into the tile statistics, and per texture into texture_sources,
// named by the textures (alive for the pass) that own the regions.
void attribute_texture_misses(const TextureReplayDetail& detail, uint64_t line_bytes,
                              PassReport& report) {
  for (size_t t = 0; t < report.tile_stats.size(); ++t) {
    report.tile_stats[t].texture_bytes_read = detail.misses_per_tile[t] * line_bytes;
  }
  for (const auto& [id, misses] : detail.misses_per_region) {
    TextureSourceTraffic source;
    if (id == 0) {
      source.name = "(outside any texture)";
    } else {
      const Texture2D::Identity identity = Texture2D::identity_of(id);
      source.name = identity.name.empty() ? "(unnamed texture)" : identity.name;
      source.render_target = identity.render_target;
    }
    source.misses = misses;
    source.bytes_read = misses * line_bytes;
    report.texture_sources.push_back(std::move(source));
  }
  std::sort(report.texture_sources.begin(), report.texture_sources.end(),
            [](const TextureSourceTraffic& a, const TextureSourceTraffic& b) {
              if (a.bytes_read != b.bytes_read) return a.bytes_read > b.bytes_read;
              if (a.name != b.name) return a.name < b.name;
              return a.render_target < b.render_target;
            });
}

}  // namespace

MemoryConfig memory_config_of(const TilerConfig& config) {
  MemoryConfig m;
  m.immediate_mode = config.architecture == Architecture::Imr;
  m.texture_cache = config.texture_cache;
  m.parameter_cache = config.parameter_cache;
  m.render_target_cache = config.render_target_cache;
  m.afbc = config.afbc;
  m.transaction_elimination = config.transaction_elimination;
  return m;
}

PassMemoryDesc describe_pass_memory(const RenderPassDesc& pass, int tile_width_px, int tile_height_px) {
  PassMemoryDesc m;
  m.name = pass.name;
  m.width_px = pass.width_px;
  m.height_px = pass.height_px;
  m.samples = pass.samples;
  m.tile_width_px = tile_width_px;
  m.tile_height_px = tile_height_px;
  m.depth_index = pass.depth_index;
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentDesc& d = pass.attachments[a];
    AttachmentMemory am;
    am.name = d.name;
    am.format = d.format;
    am.is_depth = static_cast<int>(a) == pass.depth_index;
    am.loads = d.load == LoadAction::Load && d.surface;
    am.clears = d.load == LoadAction::Clear;
    am.stores = (d.store == StoreAction::Store || d.store == StoreAction::StoreAndResolve) && d.surface;
    am.resolves = d.store == StoreAction::Resolve || d.store == StoreAction::StoreAndResolve;
    am.surface = bytes_of(d.surface);
    am.resolve_surface = bytes_of(d.resolve_surface);
    m.attachments.push_back(am);
  }
  for (const SubpassDesc& sub : pass.subpasses) m.subpass_color_outputs.push_back(sub.color_outputs);
  return m;
}

void select_tile_size(const TilerConfig& config, int color_bits_per_px, int& tile_width_px,
                      int& tile_height_px) {
  tile_width_px = config.tile_size_px;
  tile_height_px = config.tile_size_px;
  const int64_t budget_bits = int64_t{config.color_budget_bits_per_px} * config.tile_size_px *
                              config.tile_size_px;
  while (int64_t{color_bits_per_px} * tile_width_px * tile_height_px > budget_bits &&
         tile_width_px * tile_height_px > 4) {
    if (tile_height_px >= tile_width_px) {
      tile_height_px /= 2;
    } else {
      tile_width_px /= 2;
    }
  }
}

TileSize pass_tile_size(const TilerConfig& config, const RenderPassDesc& pass) {
  TileMemoryUse use;
  use.samples = pass.samples;
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    if (static_cast<int>(a) == pass.depth_index) {
      use.depth = pass.attachments[a].format;
    } else {
      use.colors.push_back(pass.attachments[a].format);
    }
  }
  switch (config.tile_size_rule) {
    case TileSizeRule::Panfrost:
      return panfrost_tile_size(use, config.tile_buffer_bytes, config.tile_buffer_pipelining_required);
    case TileSizeRule::Asahi:
      return asahi_tile_size(use);
    case TileSizeRule::Freedreno:
      return freedreno_tile_size(use, pass.width_px, pass.height_px, config.gmem);
    case TileSizeRule::Budget:
      break;
  }
  TileSize size;
  select_tile_size(config, color_bits_per_pixel(pass), size.width_px, size.height_px);
  return size;
}

PassReport execute_render_pass(const RenderPassDesc& pass, const TilerConfig& config,
                               MemoryModel& external) {
  if (config.tile_size_px < 2 || config.tile_size_px > 256 ||
      (config.tile_size_px & (config.tile_size_px - 1)) != 0) {
    throw Error("tile size " + std::to_string(config.tile_size_px) +
                " must be a power of two in 2..256");
  }
  if (config.subpixel_bits != kSubpixelBits && config.subpixel_bits != kMinSubpixelBits) {
    throw Error("subpixel precision " + std::to_string(config.subpixel_bits) + " bits: must be " +
                std::to_string(kMinSubpixelBits) + " or " + std::to_string(kSubpixelBits));
  }
  validate(pass);
  PassReport report;
  report.name = pass.name;
  report.width_px = pass.width_px;
  report.height_px = pass.height_px;
  report.samples = pass.samples;
  report.color_bits_per_px = color_bits_per_pixel(pass);
  const TileSize tile = pass_tile_size(config, pass);
  report.tile_width_px = tile.width_px;
  report.tile_height_px = tile.height_px;
  // Freedreno sizes bins from GMEM and the target, with no largest tile to fall short of.
  report.tile_size_reduced = config.tile_size_rule != TileSizeRule::Freedreno &&
                             report.tile_width_px * report.tile_height_px <
                                 config.tile_size_px * config.tile_size_px;

  TileGrid grid{pass.width_px, pass.height_px, report.tile_width_px, report.tile_height_px,
                config.subpixel_bits};
  report.tiles_total = static_cast<uint64_t>(grid.tile_count());

  const auto bin_start = std::chrono::steady_clock::now();
  const VertexOutputModel vertex_output{
      config.idvs, config.varying_precision == VaryingPrecision::Fp16 ? 2u : 4u};
  const ParameterBuffer params = bin_triangles(pass, grid, vertex_output);
  report.binning_ms = ms_since(bin_start);
  report.geometry = params.counters;
  const ParameterBufferWrites charged = external.parameter_buffer_written(
      {params.counters.parameter_bytes_written, params.counters.parameter_position_bytes_written,
       params.counters.parameter_varying_bytes_written});
  report.geometry.parameter_bytes_written = charged.bytes;
  report.geometry.parameter_position_bytes_written = charged.position_bytes;
  report.geometry.parameter_varying_bytes_written = charged.varying_bytes;

  external.begin_pass(describe_pass_memory(pass, grid.tile_width_px, grid.tile_height_px));
  const auto tiles_start = std::chrono::steady_clock::now();
  tbb::enumerable_thread_specific<TileMemory> memories;
  tbb::combinable<TileCounters> counters;
  std::vector<PixelFormat> attachment_formats;
  for (const AttachmentDesc& a : pass.attachments) attachment_formats.push_back(a.format);
  std::vector<TileTrace> traces(grid.tile_count());
  report.tile_stats.resize(grid.tile_count());
  std::atomic<uint32_t> tiles_started{0};
  TextureReplayDetail texture_detail;
  const std::unique_ptr<TextureReplayStream> texture_replay = external.texel_replay(traces, texture_detail);
  const auto run_tile = [&](int tile) {
    TileStats& stats = report.tile_stats[tile];
    stats.order = tiles_started.fetch_add(1, std::memory_order_relaxed);
    stats.thread = tbb::this_task_arena::current_thread_index();
    TileMemory& memory = memories.local();
    memory.prepare(attachment_formats, grid.tile_width_px, grid.tile_height_px, pass.samples);
    TileCounters tile_counters;
    TileTrace& trace = traces[tile];
    trace.texture_granules = take_granule_buffer();
    execute_tile(pass, params, tile, memory, tile_counters, trace, external, config.hierarchical_z);
    texture_replay->tile_recorded(static_cast<size_t>(tile));
    counters.local().add(tile_counters);
    record_tile_counters(tile_counters, params, tile, stats);
  };
  // Tiles are taken in index order by whichever worker is free (not in ranges, as
  // tbb::parallel_for splits them), so they complete nearly in order and the texture replay,
  // which follows tile order, keeps pace with them instead of waiting for the last one.
  std::atomic<int> next_tile{0};
  const int workers = std::min(grid.tile_count(), std::max(1, tbb::this_task_arena::max_concurrency()));
  ontile::parallel_for(0, workers, [&](int) {
    for (int tile = next_tile.fetch_add(1, std::memory_order_relaxed); tile < grid.tile_count();
         tile = next_tile.fetch_add(1, std::memory_order_relaxed)) {
      run_tile(tile);
    }
  });
  counters.combine_each([&](const TileCounters& c) { report.tiles.add(c); });
  report.tiles_ms = ms_since(tiles_start);
  report.texture = texture_replay->finish();
  attribute_texture_misses(texture_detail, external.texture_cache_config().line_bytes, report);
  external.fragments(traces);
  if (external.replays_parameter_reads()) replay_parameter_reads(params, pass, external);
  report.tiles.parameter_bytes_read = external.parameter_buffer_read(report.tiles.parameter_bytes_read,
                                                                     report.parameter_cache);

  PassAttachmentTraffic attachments = external.end_pass();
  report.architecture = attachments.architecture;
  report.attachments = std::move(attachments.attachments);
  report.render_target_cache_hits = attachments.render_target_cache_hits;
  report.render_target_cache_misses = attachments.render_target_cache_misses;
  report.transaction_elimination = attachments.transaction_elimination;
  for (size_t t = 0; t < report.tile_stats.size(); ++t) {
    report.tile_stats[t].bytes_loaded = attachments.tile_bytes_loaded[t];
    report.tile_stats[t].bytes_stored = attachments.tile_bytes_stored[t];
  }
  return report;
}

}  // namespace ontile
