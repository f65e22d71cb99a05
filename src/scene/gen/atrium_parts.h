// Repeated pieces of the "atrium" courtyard (columns, balustrade bays, vases), each built once
// in local coordinates and instanced by nodes. `detail` multiplies every tessellation count in
// both directions of a surface, so triangles grow with detail^2 (atrium uses detail = sqrt(size)).
#pragma once
#include "scene/gen/mesh_builder.h"

namespace ontile::gen {

// Total height of a column of the given scale with shaft_height_m of shaft.
float column_height_m(float shaft_height_m, float scale);

// A column standing on the origin, +Y up: square plinth, Attic base (two tori), shaft with
// entasis, astragal, echinus and a square abacus whose top is at column_height_m().
MeshData column_mesh(float shaft_height_m, float scale, double detail);

// Height of a balustrade (base, balusters, rail) above the floor it stands on.
float balustrade_height_m();

// One bay of balustrade centred on the origin, running along x over width_m, standing on y = 0:
// base course, a row of turned balusters and a hand rail.
MeshData balustrade_bay_mesh(float width_m, double detail);

// A turned terracotta vase standing on the origin, about 1 m tall.
MeshData vase_mesh(double detail);

}  // namespace ontile::gen
