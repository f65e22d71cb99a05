// Renderers (a mesh primitive placed in the world with a material) and culling: frustum
// culling of their world bounds and the layer mask, as Unity's ScriptableRenderContext.Cull.
#pragma once
#include <cstdint>
#include <vector>

#include "context/camera_matrices.h"
#include "context/shader.h"

namespace ontile {

struct Renderer {
  const MeshPrimitive* mesh = nullptr;
  glm::dmat4 world{1.0};
  Bounds world_bounds;
  const RenderMaterial* material = nullptr;
  uint32_t layer = 0;                  // 0..31, tested against layer masks
  uint32_t rendering_layer_mask = 1;   // tested against FilteringSettings
  uint32_t primitive_id_base = 0;      // first primitive id of the mesh's triangles
};

struct CullingParameters {
  uint32_t layer_mask = ~0u;
};

struct CullingResults {
  CameraMatrices camera;
  const std::vector<Renderer>* renderers = nullptr;
  std::vector<uint32_t> visible;  // indices into *renderers, in renderer order
};

// Keeps the renderers whose world bounds intersect the camera frustum (Gribb-Hartmann planes of
// the view-projection matrix, depth in [0, 1]) and whose layer is in the mask.
// True when the box lies entirely outside one of the frustum planes (conservative: a box near a
// frustum corner may be kept although it is outside).
bool box_outside_frustum(const glm::dmat4& view_projection, const Bounds& box);

CullingResults cull_renderers(const std::vector<Renderer>& renderers, const CameraMatrices& camera,
                              const CullingParameters& params);

}  // namespace ontile
