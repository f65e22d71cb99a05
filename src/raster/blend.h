// Output-merger blending of a shaded colour into the value already in tile memory.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

namespace ontile {

enum class BlendMode {
  Opaque,          // dst = src
  Alpha,           // dst = src * src.w + dst * (1 - src.w)  (straight alpha, "Traditional")
  Premultiplied,   // dst = src + dst * (1 - src.w)
  Additive,        // dst = src + dst
  Multiply,        // dst = src * dst
};

struct BlendState {
  BlendMode mode = BlendMode::Opaque;
  uint8_t write_mask = 0xF;  // bit 0 = R ... bit 3 = A
};

inline glm::vec4 blend_color(const BlendState& state, const glm::vec4& src, const glm::vec4& dst) {
  glm::vec4 out;
  switch (state.mode) {
    case BlendMode::Opaque: out = src; break;
    case BlendMode::Alpha: out = src * src.w + dst * (1.0f - src.w); break;
    case BlendMode::Premultiplied: out = src + dst * (1.0f - src.w); break;
    case BlendMode::Additive: out = src + dst; break;
    case BlendMode::Multiply: out = src * dst; break;
  }
  if (state.write_mask != 0xF) {
    for (int c = 0; c < 4; ++c) {
      if (!((state.write_mask >> c) & 1u)) out[c] = dst[c];
    }
  }
  return out;
}

}  // namespace ontile
