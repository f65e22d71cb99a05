// GL state and program helpers for the llvmpipe runner (see gl_state.h).
#include "gl_state.h"

#include <cstdio>

#include "util/error.h"

namespace ontile::peer {
namespace {

GLenum gl_wrap(WrapMode mode) {
  switch (mode) {
    case WrapMode::Repeat: return GL_REPEAT;
    case WrapMode::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case WrapMode::MirroredRepeat: return GL_MIRRORED_REPEAT;
  }
  return GL_REPEAT;
}

GLenum gl_min_filter(const SamplerDesc& s) {
  const bool linear = s.min_filter == FilterMode::Linear;
  switch (s.mipmap_mode) {
    case MipmapMode::None: return linear ? GL_LINEAR : GL_NEAREST;
    case MipmapMode::Nearest: return linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
    case MipmapMode::Linear: return linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
  }
  return GL_LINEAR_MIPMAP_LINEAR;
}

GLenum gl_compare(CompareOp op) {
  switch (op) {
    case CompareOp::Never: return GL_NEVER;
    case CompareOp::Less: return GL_LESS;
    case CompareOp::Equal: return GL_EQUAL;
    case CompareOp::LessEqual: return GL_LEQUAL;
    case CompareOp::Greater: return GL_GREATER;
    case CompareOp::NotEqual: return GL_NOTEQUAL;
    case CompareOp::GreaterEqual: return GL_GEQUAL;
    case CompareOp::Always: return GL_ALWAYS;
  }
  return GL_LEQUAL;
}

GLuint compile(GLenum stage, const std::string& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw Error(std::string("llvmpipe runner: shader compilation failed: ") + log);
  }
  return shader;
}

}  // namespace

void check_gl(const char* what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", e);
    throw Error(std::string("llvmpipe runner: GL error ") + code + " in " + what);
  }
}

void apply_cull(CullMode cull) {
  if (cull == CullMode::None) {
    glDisable(GL_CULL_FACE);
    return;
  }
  glEnable(GL_CULL_FACE);
  glCullFace(cull == CullMode::Back ? GL_BACK : GL_FRONT);
}

void apply_depth(const PassState& state) {
  if (state.depth_test) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(gl_compare(state.depth_compare));
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDepthMask(state.depth_write ? GL_TRUE : GL_FALSE);
}

void apply_blend(const BlendState& blend) {
  glColorMask(blend.write_mask & 1u, (blend.write_mask >> 1) & 1u, (blend.write_mask >> 2) & 1u,
              (blend.write_mask >> 3) & 1u);
  if (blend.mode == BlendMode::Opaque) {
    glDisable(GL_BLEND);
    return;
  }
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  switch (blend.mode) {  // raster/blend.h, every channel alike
    case BlendMode::Alpha: glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); break;
    case BlendMode::Premultiplied: glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA); break;
    case BlendMode::Additive: glBlendFunc(GL_ONE, GL_ONE); break;
    case BlendMode::Multiply: glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_DST_ALPHA, GL_ZERO); break;
    case BlendMode::Opaque: break;
  }
}

GLuint make_gl_sampler(const SamplerDesc& s) {
  GLuint sampler = 0;
  glGenSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(gl_min_filter(s)));
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, s.mag_filter == FilterMode::Linear ? GL_LINEAR : GL_NEAREST);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, static_cast<GLint>(gl_wrap(s.wrap_u)));
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, static_cast<GLint>(gl_wrap(s.wrap_v)));
  return sampler;
}

GLuint build_program(const std::string& vertex_source, const std::string& fragment_source) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw Error(std::string("llvmpipe runner: program link failed: ") + log);
  }
  return program;
}

}  // namespace ontile::peer
