// Architectural pieces for the generated courtyard: round-arch wall panels and hanging cloths
// with sinusoidal folds, built on the parametric grids of mesh_builder.h.
#pragma once
#include "scene/gen/mesh_builder.h"

namespace ontile::gen {

struct ArchPanelShape {
  float span_m = 4.0f;          // panel width along x, centred on x = 0
  float inner_radius_m = 1.6f;  // semicircular opening centred on (0, 0), springing at y = 0
  float height_m = 2.0f;        // panel top above the springing line (> inner_radius_m)
  float thickness_m = 0.6f;     // along z, centred on z = 0
  int arc_segments = 32;        // around the opening
  int radial_segments = 4;      // from the opening out to the panel edge
  int depth_segments = 2;       // across the soffit (intrados)
  float uv_metres_per_repeat = 2.0f;
};

// The two faces (z = +-thickness/2) with the semicircular opening go into faces; the soffit (the
// half-cylinder under the arch, normals towards the opening's centre) into soffit. Both share
// the opening's sample angles so the edge between them has no T-junctions.
void add_arch_panel(MeshData& faces, MeshData& soffit, const ArchPanelShape& shape,
                    const glm::mat4& transform = glm::mat4(1.0f));

struct ClothShape {
  float width_m = 3.0f;        // along x, centred on x = 0
  float drop_m = 4.0f;         // hangs from y = 0 down to y = -drop_m
  int fold_count = 5;          // sine periods across the width
  float fold_depth_m = 0.12f;  // fold amplitude at the bottom edge (shallower at the top)
  float billow_m = 0.15f;      // bulge towards the front (-z), growing towards the bottom
  float fold_phase_rad = 0.0f;
  int cols = 48;
  int rows = 40;
};

// A hanging curtain: z = fold(u, v) + billow(u, v) over the x-y rectangle, analytic normals
// (front side towards -z), u across the width in [0, 1] (one texture repeat), v down the drop
// with the same scale so texels stay square.
void add_cloth(MeshData& mesh, const ClothShape& shape,
               const glm::mat4& transform = glm::mat4(1.0f));

}  // namespace ontile::gen
