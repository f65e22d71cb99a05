// Toon environment lighting: the diffuse colour multiplied by a cube map looked up with the
// surface normal, in world space, or in view space with kCameraBased (the
// CAMERA_BASED_ENVIRONMENT keyword: the lighting turns with the camera, like a MatCap).
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/toon/cube_map.h"
#include "shaders_cpp/toon/toon_outputs.h"
#include "shaders_cpp/toon/toon_vertex_shader.h"
#include "util/error.h"

namespace ontile {

struct ToonEnvParams {
  const CubeMap* environment = nullptr;  // required when the colour output is written
  glm::vec4 base_color{1.0f};
  const Texture2D* base_map = nullptr;   // optional (sRGB); null = base colour factor only
  SamplerDesc base_sampler;
  ToonOutputParams outputs;
};

// Colour = (base colour [x base map]).rgb x environment(N).rgb, alpha = base alpha; N = the unit
// interpolated world normal, or view-space normal with kCameraBased (flipped on back faces).
template <uint32_t kOutputs, bool kCameraBased>
class ToonEnvShader final : public FragmentShader {
  static_assert(is_valid_toon_output_mask(kOutputs), "kOutputs must be a ToonOutput mask");

 public:
  explicit ToonEnvShader(const ToonEnvParams& params) : p_(params) {
    if ((kOutputs & ToonOutput::kColor) != 0u && !p_.environment) {
      throw Error("ToonEnvShader: no environment cube map");
    }
  }

  // Per-fragment arithmetic; texture reads quad by quad (base map, then environment per lane).
  bool batches_across_triangles() const override { return true; }
  // The view normal; for the colour the UV and (world-space lookups) the world normal: the
  // raster core interpolates only these.
  uint32_t varyings_read() const override {
    constexpr uint32_t kViewNormalBits = 7u << ToonVertexShader::kViewNormal;
    constexpr uint32_t kColorBits = (3u << ToonVertexShader::kUv) | (kCameraBased ? 0u : 7u << ToonVertexShader::kNormal);
    return kViewNormalBits | ((kOutputs & ToonOutput::kColor) != 0u ? kColorBits : 0u);
  }

  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    alignas(64) BatchVec3 view_normal;
    batch_unit_normals(batch, ToonVertexShader::kViewNormal, batch.padded_fragment_count(), view_normal);
    if constexpr ((kOutputs & ToonOutput::kColor) != 0u) shade_color(batch, view_normal, out);
    write_toon_normal_and_border<kOutputs>(batch, out, view_normal, p_.outputs);
  }

 private:
  // Texture reads per quad in the per-quad functor's order (the base map for all four lanes,
  // then the environment for each active lane), then the colour product over all fragments.
  void shade_color(const FragmentBatch& batch, const BatchVec3& view_normal, BatchOutput& out) const {
    const int n = batch.padded_fragment_count();
    alignas(64) BatchVec3 world_normal;
    if constexpr (!kCameraBased) batch_unit_normals(batch, ToonVertexShader::kNormal, n, world_normal);
    const BatchVec3& direction = kCameraBased ? view_normal : world_normal;
    alignas(64) BatchVec4 albedo;
    alignas(64) BatchVec3 env = {};
    for (int c = 0; c < 4; ++c) {
      const float value = p_.base_color[c];  // glm's operator[] is a switch: read it once
      for (int f = 0; f < n; ++f) albedo[c][f] = value;
    }
    for (int q = 0; q < batch.quad_count; ++q) {
      if (p_.base_map) {  // one branch per quad: the base map is not a keyword of this shader
        glm::vec2 uv[kQuadLanes];
        batch_quad_uv(batch, ToonVertexShader::kUv, q, uv);
        glm::vec4 texel[kQuadLanes];
        p_.base_map->sample_quad(p_.base_sampler, uv, texel);
        batch_multiply_quad(albedo, 4, q, texel);
      }
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        const int f = q * kQuadLanes + lane;
        if (batch.active(f)) batch_set3(env, f, glm::vec3(p_.environment->sample(batch_get3(direction, f))));
      }
    }
    for (int c = 0; c < 3; ++c) {
      for (int f = 0; f < n; ++f) out.color[0][c][f] = albedo[c][f] * env[c][f];
    }
    for (int f = 0; f < n; ++f) out.color[0][3][f] = albedo[3][f];
  }

  ToonEnvParams p_;
};

}  // namespace ontile
