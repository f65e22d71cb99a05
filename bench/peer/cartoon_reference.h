// ontile's side of the cartoon comparison: the `cartoon` pipeline's frame rebuilt from the
// public pieces it is made of (ToonShaderLibrary, the same MRT pass and the same edge blit),
// plus one more blit that runs ontile's SobelEdgeShader with a black scene and a white border,
// so its output is the shader's edge / no-edge decision per pixel. ontile's pipeline does not
// expose its G-buffer, hence the rebuild; the peer test checks that its final image is
// bit-identical to render_frame's.
#pragma once
#include <cstdint>
#include <vector>

#include "pipelines/kit/render_frame.h"

namespace ontile::peer {

struct CartoonReference {
  std::vector<uint8_t> final_rgba;  // the final RGBA8 sRGB image, as render_frame's `cartoon`
  std::vector<uint8_t> edge_mask;   // width x height, 1 where SobelEdgeShader finds an edge
};

// settings: size, camera and context as for render_frame (the pipeline name and options are
// ignored: `cartoon` with its defaults). Throws ontile::Error as render_frame does.
CartoonReference render_cartoon_reference(const Scene& scene, const RenderSettings& settings);

}  // namespace ontile::peer
