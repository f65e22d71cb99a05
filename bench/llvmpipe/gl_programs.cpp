// GLSL sources and variant compilation (see gl_programs.h).
#include "gl_programs.h"

#include <string>

#include "gl_state.h"

namespace ontile::peer {
namespace {

// MeshVertexShader: clip = MVP x position (MVP = view_projection x world, multiplied in double
// on the CPU and rounded to float, as ontile does), normal = inverse transpose of the world's
// 3x3 part x normal, not normalised (the fragment shader normalises).
constexpr const char* kVertexSource = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_mvp;
uniform mat3 u_normal_matrix;
out vec3 v_normal;
out vec2 v_uv;
void main() {
  gl_Position = u_mvp * vec4(a_position, 1.0);
  v_normal = u_normal_matrix * a_normal;
  v_uv = a_uv;
}
)";

// LambertShader<kBaseMap, kAlphaTest, kEmissionMap>::shade, line for line: albedo = base colour
// factor x base map (sRGB texture, decoded by the sampler), alpha test against the cutoff,
// rgb = albedo x (ambient + radiance x max(N.L, 0)) + emission factor x emission map, with the
// normal normalised (0,0,1 when degenerate) and flipped on back faces. The colour target is
// sRGB, so GL encodes the output as ontile's RGBA8_SRGB target does.
constexpr const char* kLambertSource = R"(
in vec3 v_normal;
in vec2 v_uv;
uniform vec4 u_base_color;
uniform vec3 u_emission;
uniform float u_cutoff;
uniform vec3 u_to_light;
uniform vec3 u_radiance;
uniform vec3 u_ambient;
uniform sampler2D u_base_map;
uniform sampler2D u_emission_map;
layout(location = 0) out vec4 o_color;
void main() {
  vec4 albedo = u_base_color;
#ifdef BASE_MAP
  albedo *= texture(u_base_map, v_uv);
#endif
  vec3 emissive = u_emission;
#ifdef EMISSION_MAP
  emissive *= texture(u_emission_map, v_uv).rgb;
#endif
#ifdef ALPHA_TEST
  if (albedo.a < u_cutoff) discard;
#endif
  float len = length(v_normal);
  vec3 n = len > 0.0 ? v_normal / len : vec3(0.0, 0.0, 1.0);
  if (!gl_FrontFacing) n = -n;
  float n_dot_l = max(dot(n, u_to_light), 0.0);
  o_color = vec4(albedo.rgb * (u_ambient + u_radiance * n_dot_l) + emissive, albedo.a);
}
)";

// ontile's AOV pass: the material's discards (alpha test with the base map) and the id
// draw.primitive_id_base + triangle index, which is gl_PrimitiveID within one glDrawElements.
constexpr const char* kPrimitiveIdSource = R"(
in vec3 v_normal;
in vec2 v_uv;
uniform vec4 u_base_color;
uniform float u_cutoff;
uniform sampler2D u_base_map;
uniform uint u_primitive_id_base;
layout(location = 0) out uint o_id;
void main() {
#ifdef ALPHA_TEST
  vec4 albedo = u_base_color;
#ifdef BASE_MAP
  albedo *= texture(u_base_map, v_uv);
#endif
  if (albedo.a < u_cutoff) discard;
#endif
  o_id = u_primitive_id_base + uint(gl_PrimitiveID);
}
)";

std::string header(const ProgramKey& key) {
  std::string h = "#version 320 es\nprecision highp float;\nprecision highp int;\n";
  if (key.base_map) h += "#define BASE_MAP\n";
  if (key.alpha_test) h += "#define ALPHA_TEST\n";
  if (key.emission_map) h += "#define EMISSION_MAP\n";
  return h;
}

}  // namespace

GlPrograms::~GlPrograms() {
  for (auto& [key, program] : programs_) glDeleteProgram(program.id);
}

const GlProgram& GlPrograms::get(const ProgramKey& key) {
  const auto found = programs_.find(key);
  if (found != programs_.end()) return found->second;
  GlProgram p;
  p.id = build_program(header(key) + kVertexSource,
                       header(key) + (key.primitive_ids ? kPrimitiveIdSource : kLambertSource));
  auto uniform = [&](const char* name) { return glGetUniformLocation(p.id, name); };
  p.mvp = uniform("u_mvp");
  p.normal_matrix = uniform("u_normal_matrix");
  p.base_color = uniform("u_base_color");
  p.emission = uniform("u_emission");
  p.cutoff = uniform("u_cutoff");
  p.to_light = uniform("u_to_light");
  p.radiance = uniform("u_radiance");
  p.ambient = uniform("u_ambient");
  p.primitive_id_base = uniform("u_primitive_id_base");
  glUseProgram(p.id);
  glUniform1i(uniform("u_base_map"), kBaseMapUnit);
  glUniform1i(uniform("u_emission_map"), kEmissionMapUnit);
  return programs_.emplace(key, p).first->second;
}

}  // namespace ontile::peer
