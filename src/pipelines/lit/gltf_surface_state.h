// The render state a glTF material implies, shared by every pipeline's material mapping:
// double-sided materials draw both faces, MASK materials alpha-test in the AlphaTest queue and
// BLEND materials blend in the Transparent queue without depth writes (Unity's surface types).
#pragma once
#include "pipelines/kit/pipeline_api.h"

namespace ontile {

void apply_gltf_surface_state(RenderMaterial& material, const Material& gltf);

}  // namespace ontile
