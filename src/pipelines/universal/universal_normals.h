// The Universal functors' per-fragment normal work on SIMD lanes: interpolated normals made unit
// length (batch_unit_normals' bits), and the DepthNormals pass's encoded view-space normals.
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"

namespace ontile {

// batch_unit_normals(batch, first, n, out) with the same operations per lane (n a multiple of 16).
void universal_unit_normals(const FragmentBatch& batch, int first, int n, float (&out)[3][kBatchFragments]);

// For fragments [0, n) (n a multiple of 16): the unit interpolated normal of varyings
// [first, first + 3) (batch_unit_normals), turned by world_to_view and made unit again
// (toon_unit_normal(world_to_view * n, true)), encoded n * 0.5 + 0.5 with alpha 1
// (encode_view_normal, Unorm) into encoded[c][f].
void universal_encoded_view_normals(const FragmentBatch& batch, int first, const glm::mat3& world_to_view,
                                    int n, float (&encoded)[4][kBatchFragments]);

}  // namespace ontile
