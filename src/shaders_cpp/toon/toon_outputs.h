// What a cartoon fragment functor writes: a bit mask of colour, view-space normal and border
// colour, packed into consecutive colour targets, so the MRT pass and the naive one-output-per-pass
// pipeline run the same code and write bit-identical values.
#pragma once
#include <bit>
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"

namespace ontile {

struct ToonOutput {
  static constexpr uint32_t kColor = 1u;   // shaded colour (linear RGBA)
  static constexpr uint32_t kNormal = 2u;  // view-space unit normal, encoded (NormalEncoding)
  static constexpr uint32_t kBorder = 4u;  // the material's border colour RGBA, alpha 0 = none
  static constexpr uint32_t kAll = kColor | kNormal | kBorder;
};

constexpr bool is_valid_toon_output_mask(uint32_t mask) {
  return mask != 0u && (mask & ~ToonOutput::kAll) == 0u;
}
// Colour-target index of `output` (a single bit) in a pass writing `mask`: targets are packed in
// bit order, colour first, then normal, then border (kColor|kBorder puts the border in slot 1).
constexpr int toon_output_slot(uint32_t mask, uint32_t output) {
  return std::popcount(mask & (output - 1u));
}
constexpr int toon_output_count(uint32_t mask) { return std::popcount(mask & ToonOutput::kAll); }

// How the normal target stores a view-space unit normal n:
//  Unorm: (n * 0.5 + 0.5, 1), for UNORM targets such as RGB10A2 that cannot hold negatives;
//  Float: (n, 1) unchanged, for float targets such as RGBA16F.
enum class NormalEncoding { Unorm, Float };

inline glm::vec4 encode_view_normal(glm::vec3 n, NormalEncoding encoding) {
  if (encoding == NormalEncoding::Unorm) return glm::vec4(n * 0.5f + 0.5f, 1.0f);
  return glm::vec4(n, 1.0f);
}
inline glm::vec3 decode_view_normal(glm::vec4 stored, NormalEncoding encoding) {
  if (encoding == NormalEncoding::Unorm) return glm::vec3(stored) * 2.0f - 1.0f;
  return glm::vec3(stored);
}

// Per-material settings of the normal and border outputs.
struct ToonOutputParams {
  NormalEncoding normal_encoding = NormalEncoding::Unorm;
  glm::vec4 border_color{0.0f};  // RGBA, alpha 0 = this material draws no screen-space edges
};

// An interpolated normal made unit length (a zero vector gives +Z) and turned towards the viewer
// on back faces, which are only seen on double-sided materials (as LambertShader does).
inline glm::vec3 toon_unit_normal(glm::vec3 n, bool front_facing) {
  const float len = glm::length(n);
  n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
  return front_facing ? n : -n;
}

// Writes the normal and border outputs of `kOutputs` for every fragment of the batch (padding
// included: the core ignores what it does not store); the functor writes colour (slot 0)
// itself. Shared by every toon functor so both pipelines encode identically.
template <uint32_t kOutputs>
inline void write_toon_normal_and_border(const FragmentBatch& batch, BatchOutput& out,
                                         const float (&view_normal)[3][kBatchFragments],
                                         const ToonOutputParams& params) {
  static_assert(is_valid_toon_output_mask(kOutputs), "kOutputs must be a ToonOutput mask");
  const int n = batch.padded_fragment_count();
  if constexpr ((kOutputs & ToonOutput::kNormal) != 0u) {
    auto& normal = out.color[toon_output_slot(kOutputs, ToonOutput::kNormal)];
    // encode_view_normal per channel: n * 0.5 + 0.5 for Unorm, n as is for Float; alpha 1.
    const bool unorm = params.normal_encoding == NormalEncoding::Unorm;
    for (int c = 0; c < 3; ++c) {
      for (int f = 0; f < n; ++f) {
        normal[c][f] = unorm ? view_normal[c][f] * 0.5f + 0.5f : view_normal[c][f];
      }
    }
    for (int f = 0; f < n; ++f) normal[3][f] = 1.0f;
  }
  if constexpr ((kOutputs & ToonOutput::kBorder) != 0u) {
    constexpr int kSlot = toon_output_slot(kOutputs, ToonOutput::kBorder);
    auto& border = out.color[kSlot];
    for (int c = 0; c < 4; ++c) {
      const float value = params.border_color[c];  // glm's operator[] is a switch: read it once
      for (int f = 0; f < n; ++f) border[c][f] = value;
    }
    out.uniform_outputs |= 1u << kSlot;  // the material's colour in every fragment
  }
}

}  // namespace ontile
