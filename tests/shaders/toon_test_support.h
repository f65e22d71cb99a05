// Helpers for the cartoon functor tests: hand-built 2x2 quads with chosen varyings, and small
// float textures, so functors can be run without the tiler.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"

namespace ontile::test {

// A quad at (x_px, y_px) with all varyings zero.
inline QuadFragment make_quad(int x_px, int y_px, uint8_t lane_mask, bool front_facing = true) {
  QuadFragment q;
  q.x_px = x_px;
  q.y_px = y_px;
  q.lane_mask = lane_mask;
  q.front_facing = front_facing;
  for (auto& varying : q.varyings)
    for (float& v : varying) v = 0.0f;
  return q;
}

inline void set_var3(QuadFragment& q, int first, int lane, glm::vec3 v) {
  q.varyings[first][lane] = v.x;
  q.varyings[first + 1][lane] = v.y;
  q.varyings[first + 2][lane] = v.z;
}

// A width x height float texture whose texel (x, y) is texel(x, y).
template <typename TexelFn>
std::shared_ptr<const Texture2D> make_float_texture(int width, int height, TexelFn&& texel) {
  std::vector<float> rgba(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::vec4 c = texel(x, y);
      for (int k = 0; k < 4; ++k) rgba[(static_cast<size_t>(y) * width + x) * 4 + k] = c[k];
    }
  }
  return Texture2D::from_rgba32f(width, height, std::move(rgba), "test");
}

}  // namespace ontile::test
