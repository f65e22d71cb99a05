// Tone curves that map linear HDR colour to the displayable [0, 1] range, shared by the
// universal post-processing pass and the deferred pipelines' tonemap subpass.
#pragma once
#include <glm/glm.hpp>

namespace ontile {

// Stephen Hill's fitted ACES (RRT + sRGB ODT, as Unity's ACES tonemapper), output clamped.
glm::vec3 tonemap_aces_fitted(glm::vec3 color);
// Reinhard per channel: c / (1 + c), negatives clamped to 0.
glm::vec3 tonemap_reinhard(glm::vec3 color);

}  // namespace ontile
