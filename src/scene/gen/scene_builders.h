// The individual scene generators behind generate_scene(); each builds a GeneratedScene
// in memory (deterministically) for write_glb.
#pragma once
#include "scene/gen/glb_writer.h"

namespace ontile::gen {

// Toon showcase: ground plane, a handful of primitives with cel / MatCap / toon-env materials,
// one 16:9 camera, a sun and two point lights. Independent of any size.
GeneratedScene build_demo_scene();

// Sponza-like courtyard with two storeys of arcades; triangle count ~ 250k * size.
GeneratedScene build_atrium_scene(double size);

}  // namespace ontile::gen
