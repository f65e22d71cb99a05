// Inverted-hull outlines: the mesh drawn again with its vertices pushed out along their normals
// and front faces culled, so only the rim of the enlarged back faces shows around the object,
// in a constant outline colour.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "scene/scene.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/toon/toon_outputs.h"

namespace ontile {

enum class OutlineMode {
  // Offset p + normalize(n) * thickness_object_units before the transform: the outline scales
  // with the object and thins with distance.
  ObjectSpace,
  // Constant width on screen: with clip = VP * world * p and the screen direction of the
  // normal, unit in pixels, dir_px = normalize(((n_clip.xy * clip.w - clip.xy * n_clip.w)
  // * viewport_px / 2)) (the derivative of the projected position along the world normal,
  // n_clip = VP * (n_world, 0)), the clip position moves by
  //   clip.xy += dir_px * thickness_px * 2 / viewport_px * clip.w
  // so after the divide by w the vertex lands exactly thickness_px pixels further out. Depth is
  // unchanged. A normal pointing straight at the camera has no screen direction: no offset.
  ScreenSpace,
};

struct OutlineParams {
  OutlineMode mode = OutlineMode::ScreenSpace;
  float thickness_object_units = 0.01f;  // ObjectSpace
  float thickness_px = 2.0f;             // ScreenSpace
  int viewport_width_px = 0;             // ScreenSpace: the render target size
  int viewport_height_px = 0;
};

// Needs the mesh's normals: smooth (shared) normals give a closed hull; flat-shaded meshes, whose
// corners have several normals, split apart at hard edges. Vertices without normals do not move.
class OutlineVertexShader final : public VertexShader {
 public:
  // Throws Error when ScreenSpace is asked for without a viewport size.
  OutlineVertexShader(const MeshPrimitive& primitive, const glm::dmat4& world,
                      const glm::dmat4& view_projection, const OutlineParams& params);
  int varying_count() const override { return 0; }
  void shade(uint32_t first, uint32_t count, glm::vec4* clip_positions,
             float* varyings) const override;
  // Bytes per vertex a GPU would fetch (position, normal).
  uint32_t input_vertex_bytes() const;

 private:
  const MeshPrimitive& primitive_;
  OutlineParams params_;
  glm::mat4 world_;
  glm::mat4 view_projection_;
  glm::mat4 model_view_projection_;
  glm::mat3 normal_matrix_;
  glm::vec2 half_viewport_px_;
};

// The outline colour; into an MRT it also writes the flat normal facing the camera (0, 0, 1) and
// a transparent border (0, 0, 0, 0), so outlines neither add normal edges nor get bordered.
template <uint32_t kOutputs>
class OutlineColorShader final : public FragmentShader {
  static_assert(is_valid_toon_output_mask(kOutputs), "kOutputs must be a ToonOutput mask");

 public:
  OutlineColorShader(glm::vec4 color, NormalEncoding normal_encoding)
      : color_(color), outputs_{normal_encoding, glm::vec4(0.0f)} {}

  // Constants per fragment, no texture reads.
  bool batches_across_triangles() const override { return true; }
  uint32_t varyings_read() const override { return 0; }  // constants only

  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    const int n = batch.padded_fragment_count();
    alignas(64) BatchVec3 view_normal;
    for (int f = 0; f < n; ++f) batch_set3(view_normal, f, glm::vec3(0.0f, 0.0f, 1.0f));
    if constexpr ((kOutputs & ToonOutput::kColor) != 0u) {
      for (int c = 0; c < 4; ++c) {
        for (int f = 0; f < n; ++f) out.color[0][c][f] = color_[c];
      }
    }
    write_toon_normal_and_border<kOutputs>(batch, out, view_normal, outputs_);
  }

 private:
  glm::vec4 color_;
  ToonOutputParams outputs_;
};

}  // namespace ontile
