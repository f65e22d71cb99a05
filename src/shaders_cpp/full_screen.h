// Built-in functors for procedural full-screen draws: the full-screen triangle vertex shader
// (blits, clears, the skybox, deferred lighting), a constant-colour clear and a gradient sky.
#pragma once
#include <memory>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"

namespace ontile {

// Three vertices covering the viewport at depth `depth`. Varyings: uv (0,0 = top left) and,
// when an inverse view-projection is given, the world-space view direction (3 floats).
class FullScreenVertexShader final : public VertexShader {
 public:
  static constexpr int kUv = 0;
  static constexpr int kViewDirection = 2;
  explicit FullScreenVertexShader(float depth = 0.0f, const glm::dmat4* inverse_view_projection = nullptr);
  int varying_count() const override { return 5; }
  void shade(uint32_t first, uint32_t count, glm::vec4* clip, float* varyings) const override;

 private:
  float depth_;
  glm::vec3 direction_[3];
};

// The index list of the full-screen triangle.
const uint32_t* full_screen_indices();

class ClearColorShader final : public FragmentShader {
 public:
  ClearColorShader(glm::vec4 color, int output_count) : color_(color), outputs_(output_count) {}
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override;

 private:
  glm::vec4 color_;
  int outputs_;
};

// Sky: horizon-to-zenith gradient above the horizon, a ground colour below (linear RGB).
class GradientSkyShader final : public FragmentShader {
 public:
  GradientSkyShader(glm::vec3 zenith, glm::vec3 horizon, glm::vec3 ground)
      : zenith_(zenith), horizon_(horizon), ground_(ground) {}
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override;
  int outputs_always_written() const override { return 1; }  // colour, every padded fragment

 private:
  glm::vec3 zenith_, horizon_, ground_;
};

}  // namespace ontile
