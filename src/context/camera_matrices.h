// View and projection matrices for a scene camera, in the Vulkan/D3D clip-space convention
// the raster core expects (z in [0, w], +Y up), computed in double precision.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ontile {

struct CameraMatrices {
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
  glm::dmat4 view_projection{1.0};
  glm::dvec3 position{0.0};  // camera position in world space
};

// aspect_ratio = width / height of the target; the camera's own aspect ratio, when set, is
// ignored so images are never stretched (the vertical field of view is kept).
// reversed_z maps the near plane to depth 1 and the far plane (or infinity) to 0, which spends
// the float depth buffer's dense values near 0 on far surfaces (Reed, "Depth Precision
// Visualized", 2015); pipelines using it clear depth to 0 and test with GreaterEqual.
CameraMatrices camera_matrices(const Camera& camera, double aspect_ratio, bool reversed_z = false);

}  // namespace ontile
