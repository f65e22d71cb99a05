// The contract between the raster core and C++ "shader" functors: vertex shaders write clip
// positions and varyings; fragment shaders shade one 2x2 quad at a time (so they can take
// derivatives) and may read their own pixel of input attachments (framebuffer fetch).
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/raster_types.h"

namespace ontile {

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

class FragmentShader {
 public:
  virtual ~FragmentShader() = default;
  // Writes color[k][lane] for each output k of the subpass and each active lane. Called
  // concurrently for different tiles: must not mutate shared state.
  virtual void shade(const QuadFragment& quad, QuadOutput& out) const = 0;
  // True when shade() may discard: the depth test then runs after shading (late Z).
  virtual bool may_discard() const { return false; }
  // True to run once per covered sample at the sample's position instead of once per pixel
  // (Vulkan sampleShadingEnable); with one sample per pixel it changes nothing.
  virtual bool per_sample_shading() const { return false; }
};

}  // namespace ontile
