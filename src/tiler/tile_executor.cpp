// Per-tile replay of the primitive list (see tile_executor.h): coverage, early or late depth
// test, quad shading with perspective-correct varyings, blending and quantised writes.
#include "tiler/tile_executor.h"

#include <bit>

#include "raster/rasterize.h"
#include "raster/texel_trace.h"
#include "tiler/tile_load_store.h"
#include "util/error.h"

namespace ontile {
namespace {

// Framebuffer fetch from this tile's memory (Vulkan subpassLoad): the quad passes its own
// pixel coordinates, so only the current pixel is reachable.
class TileFetch final : public FramebufferFetch {
 public:
  TileFetch(const TileMemory& memory, const TileRect& rect, const std::vector<int>& inputs,
            int depth_index)
      : memory_(memory), rect_(rect), inputs_(inputs), depth_index_(depth_index) {}
  glm::vec4 load(int input_slot, int x_px, int y_px, int sample) const override {
    if (input_slot < 0 || input_slot >= static_cast<int>(inputs_.size())) {
      throw Error("framebuffer fetch of input slot " + std::to_string(input_slot) +
                  ", but the subpass declares " + std::to_string(inputs_.size()) + " inputs");
    }
    const int attachment = inputs_[input_slot];
    const size_t i = memory_.index(x_px - rect_.x0, y_px - rect_.y0, sample);
    if (attachment == depth_index_) return {memory_.depth_plane()[i], 0.0f, 0.0f, 1.0f};
    return memory_.color_plane(attachment)[i];
  }

 private:
  const TileMemory& memory_;
  const TileRect& rect_;
  const std::vector<int>& inputs_;
  int depth_index_;
};

uint8_t lanes_of(QuadCoverage coverage) {
  uint8_t lanes = 0;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (lane_coverage(coverage, lane)) lanes |= static_cast<uint8_t>(1u << lane);
  }
  return lanes;
}

struct TriangleContext {
  const RenderPassDesc& pass;
  const SubpassDesc& subpass;
  const DrawCall& draw;
  const BinnedTriangle& tri;
  const float* varyings;  // 3 * varying_count, setup slot order
  int varying_count;
  const SamplePattern& pattern;
  const TileRect& rect;
  const TileFetch* fetch;
  uint32_t triangle_ref;
  std::vector<FragmentAccess>* fragments;  // null unless recording for the IMR model
};

// Records, per covered pixel, which samples were covered and written and what was accessed.
void record_fragments(const TriangleContext& ctx, int qx, int qy, QuadCoverage coverage,
                      QuadCoverage written, bool depth_test, bool depth_write, bool write_color) {
  const bool blend_reads = ctx.draw.blend.mode != BlendMode::Opaque || ctx.draw.blend.write_mask != 0xF;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    const uint8_t covered = static_cast<uint8_t>(lane_coverage(coverage, lane));
    if (!covered) continue;
    FragmentAccess f;
    f.triangle_ref = ctx.triangle_ref;
    f.x_px = static_cast<uint16_t>(qx + (lane & 1));
    f.y_px = static_cast<uint16_t>(qy + (lane >> 1));
    f.covered_samples = covered;
    f.written_samples = static_cast<uint8_t>(lane_coverage(written, lane));
    f.subpass = static_cast<uint8_t>(ctx.tri.subpass);
    if (depth_test) f.flags |= kDepthRead;
    if (f.written_samples && depth_write) f.flags |= kDepthWritten;
    if (f.written_samples && write_color && !ctx.subpass.color_outputs.empty()) {
      f.flags |= kColorWritten;
      if (blend_reads) f.flags |= kColorRead;
    }
    ctx.fragments->push_back(f);
  }
}

// Runs the fragment shader on one quad with varyings and depth interpolated at the given
// offset inside each pixel (helper lanes get extrapolated values so derivatives exist).
void shade_quad(const TriangleContext& ctx, int qx, int qy, uint8_t lane_mask, int32_t off_x,
                int32_t off_y, int sample, QuadOutput& out) {
  const TriangleSetup& t = ctx.tri.setup;
  // Outputs a shader leaves unwritten (e.g. a sky in an MRT subpass) are defined as zero, so
  // images never depend on stack contents.
  for (size_t k = 0; k < ctx.subpass.color_outputs.size(); ++k) {
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[k][lane] = glm::vec4(0.0f);
  }
  QuadFragment quad;
  quad.x_px = qx;
  quad.y_px = qy;
  quad.lane_mask = lane_mask;
  quad.sample = sample;
  quad.front_facing = t.front_facing;
  quad.primitive_id = ctx.tri.primitive_id;
  quad.fetch = ctx.fetch;
  const int n = ctx.varying_count;
  const float* v0 = ctx.varyings;
  const float* v1 = v0 + n;
  const float* v2 = v1 + n;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    double bary[3];
    screen_barycentrics(t, int64_t{qx + (lane & 1)} * kSubpixelScale + off_x,
                        int64_t{qy + (lane >> 1)} * kSubpixelScale + off_y, bary);
    quad.depth[lane] = interpolate_depth(t, bary);
    float w[3];
    perspective_weights(t, bary, w);
    for (int k = 0; k < n; ++k) quad.varyings[k][lane] = w[0] * v0[k] + w[1] * v1[k] + w[2] * v2[k];
  }
  ctx.draw.fragment_shader->shade(quad, out);
}

// Coverage bits of sample 0 in every lane; shifted left by s for sample s.
constexpr QuadCoverage kSampleBits = 1u | (1u << kMaxSamples) | (1u << (2 * kMaxSamples)) |
                                     (1u << (3 * kMaxSamples));

void shade_and_write_quad(const TriangleContext& ctx, int qx, int qy, QuadCoverage coverage,
                          TileMemory& memory, TileCounters& counters) {
  const TriangleSetup& t = ctx.tri.setup;
  const DrawCall& draw = ctx.draw;
  const bool has_depth = ctx.pass.depth_index >= 0;
  const bool depth_test = has_depth && draw.raster.depth_test;
  const bool depth_write = has_depth && draw.raster.depth_write && !ctx.subpass.depth_read_only;
  const bool late_z = draw.fragment_shader && draw.fragment_shader->may_discard();
  const int samples = ctx.pattern.count;
  float* depth_plane = memory.depth_plane();
  // A fixed-point depth attachment (D16, D24S8) converts the fragment's depth to its format
  // before the depth test (Vulkan 1.3 "Depth Test", Fixed-Point Data Conversions): tile memory
  // keeps floats, so the incoming depth is quantised here and the quantised value is tested
  // and written. D32F keeps the float as it is.
  const PixelFormat depth_format = has_depth ? ctx.pass.attachments[ctx.pass.depth_index].format
                                             : PixelFormat::D32_FLOAT;
  const int depth_unorm_bits = depth_format == PixelFormat::D16_UNORM ? 16
                               : depth_format == PixelFormat::D24S8   ? 24
                                                                      : 0;

  // Depth at every covered sample, tested against tile memory.
  float sample_depth[kQuadLanes][kMaxSamples];
  QuadCoverage passing = coverage;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (!lane_coverage(coverage, lane)) continue;
    const int64_t px = int64_t{qx + (lane & 1)} * kSubpixelScale;
    const int64_t py = int64_t{qy + (lane >> 1)} * kSubpixelScale;
    for (int s = 0; s < samples; ++s) {
      const int bit = lane * kMaxSamples + s;
      if (!((coverage >> bit) & 1u)) continue;
      double bary[3];
      screen_barycentrics(t, px + ctx.pattern.x[s], py + ctx.pattern.y[s], bary);
      sample_depth[lane][s] = interpolate_depth(t, bary);
      if (depth_unorm_bits) {
        sample_depth[lane][s] = unorm_to_float(float_to_unorm(sample_depth[lane][s], depth_unorm_bits),
                                               depth_unorm_bits);
      }
      if (depth_test) {
        const size_t i = memory.index(qx + (lane & 1) - ctx.rect.x0, qy + (lane >> 1) - ctx.rect.y0, s);
        if (!depth_compare_passes(draw.raster.depth_compare, sample_depth[lane][s], depth_plane[i])) {
          passing &= ~(QuadCoverage{1} << bit);
        }
      }
    }
  }
  const uint8_t covered_lanes = lanes_of(coverage);
  if (!late_z) {
    counters.fragments_depth_rejected += std::popcount(static_cast<unsigned>(covered_lanes & ~lanes_of(passing)));
    if (!passing) {
      if (ctx.fragments) record_fragments(ctx, qx, qy, coverage, 0, depth_test, depth_write, false);
      return;
    }
  }

  // Shading: once per pixel at the centre, or once per sample at the sample position when the
  // shader asks (Vulkan sample shading). Each invocation's discards remove only its samples.
  const bool per_sample = draw.fragment_shader && draw.fragment_shader->per_sample_shading();
  const int invocations = per_sample ? samples : 1;
  QuadOutput outputs_by_sample[kMaxSamples];
  if (draw.fragment_shader) {
    for (int inv = 0; inv < invocations; ++inv) {
      const QuadCoverage sample_bits = per_sample ? kSampleBits << inv : ~QuadCoverage{0};
      const uint8_t lanes = lanes_of((late_z ? coverage : passing) & sample_bits);
      if (!lanes) continue;
      QuadOutput& out = outputs_by_sample[inv];
      const int32_t off_x = per_sample ? ctx.pattern.x[inv] : kSubpixelScale / 2;
      const int32_t off_y = per_sample ? ctx.pattern.y[inv] : kSubpixelScale / 2;
      shade_quad(ctx, qx, qy, lanes, off_x, off_y, per_sample ? inv : -1, out);
      counters.fragments_shaded += std::popcount(static_cast<unsigned>(lanes));
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        if ((out.discard_mask >> lane) & 1u) {
          const QuadCoverage lane_bits = (QuadCoverage{0xFF} << (lane * kMaxSamples)) & sample_bits;
          passing &= ~lane_bits;
          coverage &= ~lane_bits;
        }
      }
    }
    if (late_z) {
      counters.fragments_depth_rejected +=
          std::popcount(static_cast<unsigned>(lanes_of(coverage) & ~lanes_of(passing)));
    }
  }

  const std::vector<int>& outputs = ctx.subpass.color_outputs;
  const bool write_color = draw.fragment_shader != nullptr;
  if (ctx.fragments) record_fragments(ctx, qx, qy, coverage, passing, depth_test, depth_write, write_color);
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    const unsigned lane_bits = lane_coverage(passing, lane);
    if (!lane_bits) continue;
    for (int s = 0; s < samples; ++s) {
      if (!((lane_bits >> s) & 1u)) continue;
      const size_t i = memory.index(qx + (lane & 1) - ctx.rect.x0, qy + (lane >> 1) - ctx.rect.y0, s);
      if (depth_write) depth_plane[i] = sample_depth[lane][s];
      if (write_color) {
        const QuadOutput& out = outputs_by_sample[per_sample ? s : 0];
        for (size_t k = 0; k < outputs.size(); ++k) {
          const int a = outputs[k];
          glm::vec4& dst = memory.color_plane(a)[i];
          dst = quantize_pixel(ctx.pass.attachments[a].format,
                               blend_color(draw.blend, out.color[k][lane], dst));
        }
      }
      ++counters.samples_written;
    }
  }
}

}  // namespace

void execute_tile(const RenderPassDesc& pass, const ParameterBuffer& params, int tile_index,
                  TileMemory& memory, TileCounters& counters, TileTrace& trace,
                  bool record_fragment_accesses) {
  const TexelTraceScope texel_trace(&trace.texture_granules);
  const TileGrid& grid = params.grid;
  TileRect rect;
  rect.x0 = (tile_index % grid.tiles_x()) * grid.tile_width_px;
  rect.y0 = (tile_index / grid.tiles_x()) * grid.tile_height_px;
  rect.width = std::min(grid.tile_width_px, grid.width_px - rect.x0);
  rect.height = std::min(grid.tile_height_px, grid.height_px - rect.y0);

  load_tile(pass, rect, memory);
  const uint32_t begin = params.tile_offsets[tile_index];
  const uint32_t end = params.tile_offsets[tile_index + 1];
  if (begin != end) ++counters.tiles_executed;

  const SamplePattern& pattern = *standard_sample_pattern(pass.samples);
  const PixelRect pixel_rect{rect.x0, rect.y0, rect.x0 + rect.width, rect.y0 + rect.height};
  for (uint32_t e = begin; e < end; ++e) {
    const uint32_t ref = params.tile_entries[e];
    const BinnedTriangle& tri = params.triangle(ref);
    const SubpassDesc& subpass = pass.subpasses[tri.subpass];
    const DrawCall& draw = subpass.draws[tri.draw];
    const int n = draw.vertex_shader->varying_count();
    counters.parameter_bytes_read += kTileListEntryBytes + kPrimitiveRecordBytes +
                                     3u * post_transform_vertex_bytes(n);
    const TileFetch fetch(memory, rect, subpass.inputs, pass.depth_index);
    const TriangleContext ctx{pass, subpass, draw, tri, params.varyings(ref, tri), n, pattern,
                              rect, &fetch, ref, record_fragment_accesses ? &trace.fragments : nullptr};
    rasterize_quads(tri.setup, pattern, pixel_rect, [&](int qx, int qy, QuadCoverage coverage) {
      shade_and_write_quad(ctx, qx, qy, coverage, memory, counters);
    });
  }
  store_tile(pass, rect, memory);
}

}  // namespace ontile
