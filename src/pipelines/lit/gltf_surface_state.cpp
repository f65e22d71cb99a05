// glTF alpha mode and double-sidedness as render state (see gltf_surface_state.h).
#include "pipelines/lit/gltf_surface_state.h"

namespace ontile {

void apply_gltf_surface_state(RenderMaterial& m, const Material& gltf) {
  if (gltf.double_sided) m.cull = CullMode::None;
  switch (gltf.alpha_mode) {
    case AlphaMode::Opaque: break;
    case AlphaMode::Mask:  // glTF 2.0 3.9.4: discard below alphaCutoff
      m.keywords.insert("_ALPHATEST_ON");
      m.render_queue = render_queue::kAlphaTest;
      break;
    case AlphaMode::Blend:
      m.render_queue = render_queue::kTransparent;
      m.blend = BlendMode::Alpha;
      m.depth_write = false;
      break;
  }
}

}  // namespace ontile
