// GL helpers shared by the runner's frames: ontile render state (cull, depth, blend, samplers)
// turned into GLES 3.2 state, program compilation, and GL error checks.
#pragma once
#include <string>

#include <GLES3/gl32.h>

#include "context/shader.h"
#include "raster/texture.h"

namespace ontile::peer {

// Throws ontile::Error naming `what` when GL reports an error.
void check_gl(const char* what);

void apply_cull(CullMode cull);
// Depth test, compare op and depth writes of `state`.
void apply_depth(const PassState& state);
// raster/blend.h's modes, every channel alike, and the write mask.
void apply_blend(const BlendState& blend);

// A GL sampler object with the filters and wrap modes of `sampler` (the caller deletes it).
GLuint make_gl_sampler(const SamplerDesc& sampler);

// Compiles and links a vertex and a fragment shader (GLSL ES 3.20 sources, header included);
// throws ontile::Error with the compiler's or linker's log.
GLuint build_program(const std::string& vertex_source, const std::string& fragment_source);

}  // namespace ontile::peer
