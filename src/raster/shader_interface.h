// The contract between the raster core and C++ "shader" functors: vertex shaders write clip
// positions and varyings; fragment shaders shade batches of 2x2 quads (quads so they can take
// derivatives, batches so the per-fragment cost is arithmetic on structure-of-arrays lanes, not
// calls) and may read their own pixel of input attachments (framebuffer fetch).
#pragma once
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "raster/pixel_format.h"
#include "raster/raster_types.h"

namespace ontile {

class Texture2D;

class VertexShader {
 public:
  virtual ~VertexShader() = default;
  // Floats per vertex handed to the fragment shader (at most kMaxVaryings).
  virtual int varying_count() const = 0;
  // Shades vertices [first, first + count) of the draw. Writes count clip-space positions
  // (Vulkan/D3D clip space: x, y in [-w, w], z in [0, w], +Y up) and count * varying_count()
  // floats. Called concurrently on disjoint ranges: must not mutate shared state.
  virtual void shade(uint32_t first, uint32_t count, glm::vec4* clip_positions,
                     float* varyings) const = 0;
};

// Reads the current pixel of an input attachment from tile memory (Vulkan subpassLoad): the
// coordinates always come from the quad itself, so reading a neighbour cannot be expressed.
class FramebufferFetch {
 public:
  virtual ~FramebufferFetch() = default;
  virtual glm::vec4 load(int input_slot, int x_px, int y_px, int sample) const = 0;
  // load() of every lane of quads [0, quad_count) (top-left pixels quad_x_px, quad_y_px) into
  // channel[c][quad * 4 + lane]: one call per batch instead of one per fragment. Reads have no
  // side effects, so helper lanes are read too. For a depth input channels 1..3 (0, 0, 1) may be
  // null, and are then not written. Default: load() lane by lane.
  virtual void load_quads(int input_slot, const int32_t* quad_x_px, const int32_t* quad_y_px, int quad_count,
                          int sample, float* const channel[4]) const;
};

// Lane order inside a quad: 0 = (x, y), 1 = (x+1, y), 2 = (x, y+1), 3 = (x+1, y+1).
constexpr int kQuadLanes = 4;

struct QuadFragment {
  int x_px = 0, y_px = 0;        // top-left pixel of the quad, render-target coordinates
  uint8_t lane_mask = 0;         // lanes with at least one covered sample (others are helpers)
  bool front_facing = true;
  uint32_t primitive_id = 0;     // stable id of the drawn triangle (see DrawCall)
  int sample = -1;               // the sample being shaded (sample shading), -1 = whole pixel
  float depth[kQuadLanes] = {};  // depth at the shading position, [0, 1]
  // Perspective-correct varyings at the shading positions (pixel centres, or the sample being
  // shaded), structure-of-arrays: varyings[i][lane].
  // Helper lanes hold extrapolated values so derivatives are defined.
  float varyings[kMaxVaryings][kQuadLanes];
  const FramebufferFetch* fetch = nullptr;

  bool lane_active(int lane) const { return (lane_mask >> lane) & 1u; }
  float var(int index, int lane) const { return varyings[index][lane]; }
  glm::vec2 var2(int first, int lane) const {
    return {varyings[first][lane], varyings[first + 1][lane]};
  }
  glm::vec3 var3(int first, int lane) const {
    return {varyings[first][lane], varyings[first + 1][lane], varyings[first + 2][lane]};
  }
  glm::vec4 var4(int first, int lane) const {
    return {varyings[first][lane], varyings[first + 1][lane], varyings[first + 2][lane],
            varyings[first + 3][lane]};
  }
  // Framebuffer fetch of input slot `input_slot` at this lane's own pixel: the sample being
  // shaded, or sample `which` (0 when shading whole pixels).
  glm::vec4 input(int input_slot, int lane, int which = -1) const {
    const int s = which >= 0 ? which : (sample >= 0 ? sample : 0);
    return fetch->load(input_slot, x_px + (lane & 1), y_px + (lane >> 1), s);
  }
};

struct QuadOutput {
  glm::vec4 color[kMaxColorTargets][kQuadLanes];
  uint8_t discard_mask = 0;  // lanes the shader discarded
  void discard(int lane) { discard_mask |= static_cast<uint8_t>(1u << lane); }
};

// Up to kBatchQuads quads, in the tile's row-major quad order, shaded by one call: quads of one
// triangle, or of consecutive triangles of one draw with one facing when the functor allows it
// (FragmentShader::batches_across_triangles). Structure-of-arrays: fragment f is lane (f & 3)
// of quad (f >> 2). Arrays are valid up
// to padded_fragment_count() (a multiple of 16, so any SIMD width runs whole vectors); the
// padding repeats the last quad and its outputs are ignored.
constexpr int kBatchQuads = 16;
constexpr int kBatchFragments = kBatchQuads * kQuadLanes;

struct FragmentBatch {
  int quad_count = 0;
  int varying_count = 0;       // floats per fragment in varyings
  int color_output_count = 0;  // colour outputs of the subpass
  bool front_facing = true;
  uint32_t primitive_id = 0;   // of quad 0's triangle; quad_primitive_id holds every quad's
  int sample = -1;             // as QuadFragment::sample
  const FramebufferFetch* fetch = nullptr;
  uint32_t quad_primitive_id[kBatchQuads] = {};
  int32_t quad_x_px[kBatchQuads] = {};
  int32_t quad_y_px[kBatchQuads] = {};
  uint8_t lane_mask[kBatchQuads] = {};
  alignas(64) float depth[kBatchFragments];
  alignas(64) float varyings[kMaxVaryings][kBatchFragments];

  int fragment_count() const { return quad_count * kQuadLanes; }
  int padded_fragment_count() const { return (fragment_count() + 15) & ~15; }
  bool active(int f) const { return (lane_mask[f >> 2] >> (f & 3)) & 1u; }
  // Bit f set for every active fragment f (lane_mask of all quads).
  uint64_t active_mask() const {
    uint64_t mask = 0;
    for (int q = 0; q < quad_count; ++q) mask |= uint64_t{lane_mask[q] & 0xFu} << (q * kQuadLanes);
    return mask;
  }
  int x_px(int f) const { return quad_x_px[f >> 2] + (f & 1); }
  int y_px(int f) const { return quad_y_px[f >> 2] + ((f >> 1) & 1); }
  // Framebuffer fetch at fragment f's own pixel (see QuadFragment::input).
  glm::vec4 input(int input_slot, int f, int which = -1) const {
    const int s = which >= 0 ? which : (sample >= 0 ? sample : 0);
    return fetch->load(input_slot, x_px(f), y_px(f), s);
  }
  // input() of every fragment (active or not) into channel[c][f].
  void inputs(int input_slot, float* const channel[4]) const {
    fetch->load_quads(input_slot, quad_x_px, quad_y_px, quad_count, sample >= 0 ? sample : 0, channel);
  }
  // Quad q as a QuadFragment, for helpers written per quad (texture LOD from derivatives).
  void quad(int q, QuadFragment& out) const;
};

struct BatchOutput {
  alignas(64) float color[kMaxColorTargets][4][kBatchFragments];  // [target][channel][fragment]
  uint64_t discard_mask = 0;                                      // bit f: fragment f discarded
  // Set by a functor when every value of output 0 (padding included) is a decoded code of this
  // RGBA8 format (a nearest copy of its texels): quantising such values into an attachment of
  // the same format gives each back unchanged (PixelRows test), so the batcher skips it. The
  // batcher clears it before every call.
  std::optional<PixelFormat> output0_codes_of;
  // Bit k set by a functor when every fragment of output k (padding included) holds fragment
  // 0's values: a per-draw constant, or an output it never writes (the batcher's zeros). The
  // whole-tile path then quantises one pixel and copies it. The batcher clears it before every
  // call; bits past the subpass's outputs are ignored.
  uint32_t uniform_outputs = 0;

  void discard(int f) { discard_mask |= uint64_t{1} << f; }
  bool discarded(int f) const { return (discard_mask >> f) & 1u; }
  void set(int target, int f, const glm::vec4& c) {
    for (int ch = 0; ch < 4; ++ch) color[target][ch][f] = c[ch];
  }
  glm::vec4 get(int target, int f) const {
    return {color[target][0][f], color[target][1][f], color[target][2][f], color[target][3][f]};
  }
  // Copies quad q of `quad_out` (targets [0, targets)) into this batch output.
  void store_quad(int q, const QuadOutput& quad_out, int targets);
};

class FragmentShader {
 public:
  virtual ~FragmentShader() = default;
  // A functor overrides at least one of shade() and shade_batch(); each default runs the other.
  // Writes color[k][lane] for each output k of the subpass and each active lane. Called
  // concurrently for different tiles: must not mutate shared state.
  virtual void shade(const QuadFragment& quad, QuadOutput& out) const;
  // The raster core's entry point: writes every active fragment's outputs. The default loops
  // over the quads through shade() (for functors no benchmark uses).
  virtual void shade_batch(const FragmentBatch& batch, BatchOutput& out) const;
  // True when shade() may discard: the depth test then runs after shading (late Z).
  virtual bool may_discard() const { return false; }
  // True to run once per covered sample at the sample's position instead of once per pixel
  // (Vulkan sampleShadingEnable); with one sample per pixel it changes nothing.
  virtual bool per_sample_shading() const { return false; }
  // True when a batch may hold quads of several consecutive triangles of one draw (with one
  // facing): the functor's outputs for a quad depend only on that quad's inputs (never on
  // batch.primitive_id, which is quad 0's; quad_primitive_id is per quad), and it reads every
  // texel of quad q before any texel of quad q + 1, so the texel trace is the same whatever
  // the batch boundaries. Batches then hold up to kBatchQuads quads instead of one triangle's.
  virtual bool batches_across_triangles() const { return false; }
  // Bit k set when shade_batch (and shade, through it) reads varying k of its batches; the
  // raster core may leave the others unwritten (full-screen passes read 2 of 5, or none).
  virtual uint32_t varyings_read() const { return ~uint32_t{0}; }
  // How many leading colour outputs shade_batch writes in full, every channel of every active
  // fragment: the raster core's whole-tile batches then skip zeroing them first (unwritten
  // outputs read as zero; see BatchOutput).
  virtual int outputs_always_written() const { return 0; }
  // Non-null when the functor is a plain texel copy of this texture: output 0 of fragment (x, y)
  // is texel (x, y) of its base level as fetched (decoded, no filter, tint or conversion), read
  // once per fragment in lane order; no other output, discard or input. The raster core may then
  // move the texels' stored bytes into an attachment of the same 8-bit format without decoding
  // them (texel_copy_rect.h): the same bits and the same texel trace.
  virtual const Texture2D* texel_copy_source() const { return nullptr; }
};

}  // namespace ontile
