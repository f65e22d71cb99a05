// The deferred lighting functor's per-fragment decode over a whole batch on SIMD lanes: G-buffer
// values to BRDF inputs and unit normals (decode_gbuffer), and depth back to the world position
// and view direction, with the scalar code's operations in its order, so every bit matches.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/deferred/gbuffer_layout.h"

namespace ontile {

// What a batch's fragments read: depth and the layout's targets (structure-of-arrays), and the
// pixel each fragment shades. Only fragments whose bit is set in `lit` are decoded.
struct GBufferLanes {
  alignas(64) float depth[kBatchFragments];
  alignas(64) float targets[3][4][kBatchFragments];  // [target][channel][fragment]
  alignas(64) int32_t x_px[kBatchFragments];
  alignas(64) int32_t y_px[kBatchFragments];
  uint64_t lit = 0;
};

// Pixel centre and depth back to the world: NDC x = (x + 0.5) / width * 2 - 1, y = 1 - (y +
// 0.5) / height * 2 (Vulkan clip space, +Y up), through the inverse view-projection in double.
struct ViewReconstruction {
  glm::dmat4 inverse_view_projection{1.0};
  glm::dvec3 camera_position{0.0};
  int width_px = 1, height_px = 1;

  // The scalar reference: glm's operations, in double so distant pixels keep their precision.
  glm::dvec3 world_position(int x, int y, float depth) const {
    const glm::dvec4 ndc((x + 0.5) / width_px * 2.0 - 1.0, 1.0 - (y + 0.5) / height_px * 2.0, depth, 1.0);
    const glm::dvec4 w = inverse_view_projection * ndc;
    return glm::dvec3(w) / w.w;
  }
  glm::vec3 to_view(const glm::dvec3& world) const { return glm::vec3(glm::normalize(camera_position - world)); }
};

// Bit f set for f < count (at most kBatchFragments) where depth[f] < 1 (a NaN is not): the
// fragments in front of the far plane, a compare per SIMD lane instead of a shift per fragment.
uint64_t in_front_of_far_plane(const float* depth, int count);

// For fragments f < count (a multiple of 4) lit in `in`: brdf and normal as decode_gbuffer
// gives them, world = vec3(view.world_position(...)), to_view = view.to_view(world in double);
// zero for the others (the lighting loops read every lane).
void decode_gbuffer_lanes(const GBufferLayout& layout, const ViewReconstruction& view, const GBufferLanes& in,
                          int count, BrdfBatch& brdf, BatchVec3& normal, BatchVec3& world, BatchVec3& to_view);

}  // namespace ontile
