// GLSL sources of the cartoon frame (see gl_cartoon_programs.h). Each function follows the C++
// functor it names operation for operation; `precise` keeps the compiler from fusing or
// reordering them (GLSL ES 3.20 section 4.7.1), as ontile builds with -ffp-contract=off.
#include "gl_cartoon_programs.h"

#include <string>

#include "gl_state.h"

namespace ontile::peer {
namespace {

constexpr const char* kHeader = "#version 320 es\nprecision highp float;\nprecision highp int;\n";

// ToonVertexShader: clip = MVP x position, the world normal (inverse transpose of the world's
// 3x3 part) and the view normal (inverse transpose of view x world), neither normalised.
constexpr const char* kToonVertexSource = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_mvp;
uniform mat3 u_normal_matrix;
uniform mat3 u_view_normal_matrix;
out vec3 v_normal;
out vec3 v_view_normal;
out vec2 v_uv;
void main() {
  gl_Position = u_mvp * vec4(a_position, 1.0);
  v_normal = u_normal_matrix * a_normal;
  v_view_normal = u_view_normal_matrix * a_normal;
  v_uv = a_uv;
}
)";

// The MRT functors: colour (CelShader, MatCapShader or ToonEnvShader), the view normal encoded
// for RGB10A2 (write_toon_normal_and_border: n * 0.5 + 0.5, alpha 1) and the border colour.
constexpr const char* kToonFragmentSource = R"(
in vec3 v_normal;
in vec3 v_view_normal;
in vec2 v_uv;
uniform vec3 u_to_light;
uniform int u_steps;
uniform float u_step_size;
uniform vec4 u_lit_color;
uniform vec4 u_shadow_color;
uniform vec4 u_base_color;
uniform vec4 u_border_color;
uniform sampler2D u_base_map;
uniform sampler2D u_matcap;
uniform highp sampler2DArray u_environment;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_border;

// batch_unit_normals: length sqrt((x x + y y) + z z), (0, 0, 1) when zero, flipped on back faces.
vec3 unit_normal(vec3 v) {
  precise float len = sqrt((v.x * v.x + v.y * v.y) + v.z * v.z);
  precise vec3 n = len > 0.0 ? v / len : vec3(0.0, 0.0, 1.0);
  return gl_FrontFacing ? n : -n;
}

// cel_shadow_factor: 0 when lit, else min(1, ceil(-d / step_size) / steps); NaN gives 1.
float cel_shadow(float n_dot_l) {
  if (n_dot_l >= 0.0) return 0.0;
  precise float bands = ceil(-n_dot_l / u_step_size) / float(u_steps);
  return bands < 1.0 ? bands : 1.0;
}

// CubeMap::sample: cube_face_coord's face selection (ties to z over y over x), then a bilinear,
// clamped read of the face's base level; faces are the layers +X, -X, +Y, -Y, +Z, -Z.
vec4 environment(vec3 d) {
  float ax = abs(d.x), ay = abs(d.y), az = abs(d.z);
  float layer, sc, tc, major;
  if (az >= ax && az >= ay) {
    major = az; layer = d.z >= 0.0 ? 4.0 : 5.0; sc = d.z >= 0.0 ? d.x : -d.x; tc = -d.y;
  } else if (ay >= ax) {
    major = ay; layer = d.y >= 0.0 ? 2.0 : 3.0; sc = d.x; tc = d.y >= 0.0 ? d.z : -d.z;
  } else {
    major = ax; layer = d.x >= 0.0 ? 0.0 : 1.0; sc = d.x >= 0.0 ? -d.z : d.z; tc = -d.y;
  }
  precise vec2 st = vec2(0.5 * (sc / major + 1.0), 0.5 * (tc / major + 1.0));
  if (!(major > 0.0) || isinf(major)) { layer = 4.0; st = vec2(0.5); }
  return textureLod(u_environment, vec3(st, layer), 0.0);
}

void main() {
  vec4 albedo = u_base_color;
#if defined(BASE_MAP) && !defined(CEL)
  albedo *= texture(u_base_map, v_uv);
#endif
  vec3 view_normal = unit_normal(v_view_normal);
#if defined(CEL)
  vec4 lit = u_lit_color, shadow = u_shadow_color;
#ifdef BASE_MAP
  vec4 texel = texture(u_base_map, v_uv);
  lit *= texel;
  shadow *= texel;
#endif
  vec3 n = unit_normal(v_normal);
  precise float n_dot_l = (n.x * u_to_light.x + n.y * u_to_light.y) + n.z * u_to_light.z;
  float t = cel_shadow(n_dot_l);
  precise vec4 color = lit * (1.0 - t) + shadow * t;
#elif defined(MATCAP)
  // matcap_uv, bilinear and clamped on the base level (matcap_sampler).
  precise vec2 matcap_uv = vec2(0.5 + 0.5 * view_normal.x, 0.5 - 0.5 * view_normal.y);
  precise vec4 color = vec4(textureLod(u_matcap, matcap_uv, 0.0).rgb * albedo.rgb, albedo.a);
#else
  precise vec4 color = vec4(albedo.rgb * environment(unit_normal(v_normal)).rgb, albedo.a);
#endif
  o_color = color;
  precise vec3 encoded = view_normal * 0.5 + 0.5;
  o_normal = vec4(encoded, 1.0);
  o_border = u_border_color;
}
)";

// FullScreenVertexShader's triangle (corners (-1,-1), (3,-1), (-1,3), NDC y up, negated for the
// runner's Y flip) at depth u_depth, with one view direction per corner for the sky.
constexpr const char* kFullScreenVertexSource = R"(
uniform vec3 u_directions[3];
out vec3 v_direction;
void main() {
  vec2 corner = gl_VertexID == 0 ? vec2(-1.0, -1.0) : (gl_VertexID == 1 ? vec2(3.0, -1.0) : vec2(-1.0, 3.0));
  gl_Position = vec4(corner.x, -corner.y, 1.0, 1.0);
  v_direction = u_directions[gl_VertexID];
}
)";

// GradientSkyShader::shade_batch per fragment.
constexpr const char* kSkyFragmentSource = R"(
in vec3 v_direction;
uniform vec3 u_zenith;
uniform vec3 u_horizon;
uniform vec3 u_ground;
layout(location = 0) out vec4 o_color;
void main() {
  vec3 d = v_direction;
  precise float len = sqrt((d.x * d.x + d.y * d.y) + d.z * d.z);
  precise float up = len > 0.0 ? d.y / len : 0.0;
  precise float above = sqrt(max(up, 0.0));
  precise float below_t = -up * 4.0;
  float below = below_t < 1.0 ? below_t : 1.0;
  precise vec3 sky = u_horizon * (1.0 - above) + u_zenith * above;
  precise vec3 earth = u_horizon * (1.0 - below) + u_ground * below;
  o_color = vec4(up >= 0.0 ? sky : earth, 1.0);
}
)";

// SobelEdgeShader::shade_lanes for one pixel: uv = the pixel centre (gl_FragCoord / size; GL row
// 0 is ontile's top row), taps at uv + (i, j) x tap_step read nearest and clamped as
// nearest_clamped_texel does, depth linearised (linearize_depth), Sobel on linear depth against
// the relative limit divided by the grazing cosine, else Sobel on the decoded normals, and the
// border colour of the nearest tap (the centre on ties, else the first in row-major order).
constexpr const char* kEdgeFragmentSource = R"(
uniform highp sampler2D u_color;
uniform highp sampler2D u_depth;
uniform highp sampler2D u_normal;
uniform highp sampler2D u_border;
uniform vec2 u_tap_step;
uniform bool u_orthographic;
uniform float u_near;
uniform float u_far;
uniform vec2 u_view_ray_scale;
uniform float u_depth_limit_scale;
uniform float u_normal_threshold;
uniform float u_min_grazing_cosine;
layout(location = 0) out vec4 o_color;

int texel_index(float u, int size) {
  precise float x = u * float(size);
  return clamp(int(floor(x)), 0, size - 1);
}

float linearize(float d) {
  d = d > 0.0 ? (d < 1.0 ? d : 1.0) : 0.0;
  precise float z;
  if (u_orthographic) {
    z = u_near + d * (u_far - u_near);
  } else if (u_far == 0.0) {
    float one_minus_d = 1.0 - d;
    z = u_near / (one_minus_d > 5.9604645e-8 ? one_minus_d : 5.9604645e-8);
  } else {
    z = u_far * u_near / (u_near + (1.0 - d) * (u_far - u_near));
  }
  return z;
}

float sobel(float v[9]) {
  precise float gx = ((v[2] - v[0]) + (v[8] - v[6])) + 2.0 * (v[5] - v[3]);
  precise float gy = ((v[6] - v[0]) + (v[8] - v[2])) + 2.0 * (v[7] - v[1]);
  precise float m = sqrt(gx * gx + gy * gy);
  return m;
}

float dot3(vec3 a, vec3 b) {
  precise float d = (a.x * b.x + a.y * b.y) + a.z * b.z;
  return d;
}

float sobel_vector(vec3 v[9]) {
  precise vec3 gx = ((v[2] - v[0]) + (v[8] - v[6])) + 2.0 * (v[5] - v[3]);
  precise vec3 gy = ((v[6] - v[0]) + (v[8] - v[2])) + 2.0 * (v[7] - v[1]);
  precise float m = sqrt(dot3(gx, gx) + dot3(gy, gy));
  return m;
}

float grazing_cosine(vec3 n, vec2 uv) {
  precise vec3 ray = vec3(u_view_ray_scale.x * (2.0 * uv.x - 1.0), u_view_ray_scale.y * (1.0 - 2.0 * uv.y), -1.0);
  precise float normal_len = sqrt(dot3(n, n));
  if (!(normal_len > 0.0)) return u_min_grazing_cosine;
  precise float cosine = abs(dot3(n, ray)) / (normal_len * sqrt(dot3(ray, ray)));
  return cosine > u_min_grazing_cosine ? cosine : u_min_grazing_cosine;
}

void main() {
  ivec2 size = textureSize(u_depth, 0);
  precise vec2 uv = gl_FragCoord.xy / vec2(size);
  ivec2 tap[3];
  for (int a = 0; a < 3; ++a) {
    precise float offset = float(a - 1);
    tap[a] = ivec2(texel_index(uv.x + offset * u_tap_step.x, size.x), texel_index(uv.y + offset * u_tap_step.y, size.y));
  }
  float depth[9], linear_z[9];
  for (int k = 0; k < 9; ++k) {
    depth[k] = texelFetch(u_depth, ivec2(tap[k % 3].x, tap[k / 3].y), 0).r;
    linear_z[k] = linearize(depth[k]);
  }
  int nearest = 4;
  for (int k = 0; k < 9; ++k) {
    if (depth[k] < depth[nearest]) nearest = k;
  }
  precise float depth_limit = u_depth_limit_scale * linear_z[4];
  vec3 normals[9];
  normals[4] = texelFetch(u_normal, ivec2(tap[1].x, tap[1].y), 0).rgb * 2.0 - 1.0;
  depth_limit /= grazing_cosine(normals[4], uv);
  bool edge = sobel(linear_z) > depth_limit;
  if (!edge) {
    for (int k = 0; k < 9; ++k) {
      normals[k] = texelFetch(u_normal, ivec2(tap[k % 3].x, tap[k / 3].y), 0).rgb * 2.0 - 1.0;
    }
    edge = sobel_vector(normals) > u_normal_threshold;
  }
#ifdef EDGE_MASK
  vec4 scene = vec4(0.0);
  vec4 border = vec4(1.0);
#else
  vec4 scene = texelFetch(u_color, ivec2(texel_index(uv.x, size.x), texel_index(uv.y, size.y)), 0);
  vec4 border = texelFetch(u_border, ivec2(tap[nearest % 3].x, tap[nearest / 3].y), 0);
#endif
  precise vec3 mixed = scene.rgb * (1.0 - border.a) + border.rgb * border.a;
  o_color = edge ? vec4(mixed, scene.a) : scene;
}
)";

std::string define(const char* name) { return std::string("#define ") + name + "\n"; }

}  // namespace

GlCartoonPrograms::GlCartoonPrograms() {
  sky_.id = build_program(std::string(kHeader) + kFullScreenVertexSource, std::string(kHeader) + kSkyFragmentSource);
  sky_.directions = glGetUniformLocation(sky_.id, "u_directions");
  sky_.zenith = glGetUniformLocation(sky_.id, "u_zenith");
  sky_.horizon = glGetUniformLocation(sky_.id, "u_horizon");
  sky_.ground = glGetUniformLocation(sky_.id, "u_ground");
  for (bool mask : {false, true}) {
    GlEdgeProgram& p = mask ? mask_ : edges_;
    p.id = build_program(std::string(kHeader) + kFullScreenVertexSource,
                         std::string(kHeader) + (mask ? define("EDGE_MASK") : "") + kEdgeFragmentSource);
    auto uniform = [&](const char* name) { return glGetUniformLocation(p.id, name); };
    p.tap_step = uniform("u_tap_step");
    p.orthographic = uniform("u_orthographic");
    p.near_plane = uniform("u_near");
    p.far_plane = uniform("u_far");
    p.view_ray_scale = uniform("u_view_ray_scale");
    p.depth_limit_scale = uniform("u_depth_limit_scale");
    p.normal_threshold = uniform("u_normal_threshold");
    p.min_grazing_cosine = uniform("u_min_grazing_cosine");
    glUseProgram(p.id);
    glUniform1i(uniform("u_color"), kEdgeColorUnit);
    glUniform1i(uniform("u_depth"), kEdgeDepthUnit);
    glUniform1i(uniform("u_normal"), kEdgeNormalUnit);
    glUniform1i(uniform("u_border"), kEdgeBorderUnit);
  }
  check_gl("compiling the cartoon programs");
}

GlCartoonPrograms::~GlCartoonPrograms() {
  for (auto& [key, program] : toon_) glDeleteProgram(program.id);
  glDeleteProgram(sky_.id);
  glDeleteProgram(edges_.id);
  glDeleteProgram(mask_.id);
}

const GlToonProgram& GlCartoonPrograms::toon(const ToonProgramKey& key) {
  const auto found = toon_.find(key);
  if (found != toon_.end()) return found->second;
  std::string defines = kHeader;
  defines += define(key.kind == ToonKind::Cel ? "CEL" : key.kind == ToonKind::MatCap ? "MATCAP" : "ENVIRONMENT");
  if (key.base_map) defines += define("BASE_MAP");
  GlToonProgram p;
  p.id = build_program(defines + kToonVertexSource, defines + kToonFragmentSource);
  auto uniform = [&](const char* name) { return glGetUniformLocation(p.id, name); };
  p.mvp = uniform("u_mvp");
  p.normal_matrix = uniform("u_normal_matrix");
  p.view_normal_matrix = uniform("u_view_normal_matrix");
  p.to_light = uniform("u_to_light");
  p.steps = uniform("u_steps");
  p.step_size = uniform("u_step_size");
  p.lit_color = uniform("u_lit_color");
  p.shadow_color = uniform("u_shadow_color");
  p.base_color = uniform("u_base_color");
  p.border_color = uniform("u_border_color");
  glUseProgram(p.id);
  glUniform1i(uniform("u_base_map"), kToonBaseMapUnit);
  glUniform1i(uniform("u_matcap"), kToonMatCapUnit);
  glUniform1i(uniform("u_environment"), kToonEnvironmentUnit);
  return toon_.emplace(key, p).first->second;
}

}  // namespace ontile::peer
