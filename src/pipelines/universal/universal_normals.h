// The Universal DepthNormals pass's per-fragment normal work on SIMD lanes: encoded view-space
// normals (the unit normals themselves are batch_unit_normals').
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"

namespace ontile {

// For fragments [0, n) (n a multiple of 16): the unit interpolated normal of varyings
// [first, first + 3) (batch_unit_normals), turned by world_to_view and made unit again
// (toon_unit_normal(world_to_view * n, true)), encoded n * 0.5 + 0.5 with alpha 1
// (encode_view_normal, Unorm) into encoded[c][f].
void universal_encoded_view_normals(const FragmentBatch& batch, int first, const glm::mat3& world_to_view,
                                    int n, float (&encoded)[4][kBatchFragments]);

}  // namespace ontile
