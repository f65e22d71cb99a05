// The cartoon frame on llvmpipe (see gl_cartoon.h).
#include "gl_cartoon.h"

#include "gl_state.h"
#include "shaders_cpp/toon/cube_map.h"
#include "shaders_cpp/toon/matcap_shader.h"
#include "shaders_cpp/toon/sobel_edge_shader.h"
#include "util/error.h"

namespace ontile::peer {
namespace {

// ToonShaderLibrary's sky cube map for ToonEnv (toon_shaders.cpp: kSkyFacePx).
constexpr int kToonSkyFacePx = 128;
// FrameExecutor's DrawSkybox colours when no _Sky* globals are set (frame_executor.cpp); the
// cartoon pipeline sets none.
const glm::vec3 kSkyZenith(0.18f, 0.32f, 0.62f), kSkyHorizon(0.62f, 0.70f, 0.80f), kSkyGround(0.25f, 0.23f, 0.21f);

constexpr GLenum kMrtBuffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
constexpr GLenum kColorOnly[3] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_NONE};

ToonKind toon_kind(const RenderMaterial& m) {
  const std::string& shader = m.shader->name();
  if (shader == "ToonCel") return ToonKind::Cel;
  if (shader == "ToonMatCap") return ToonKind::MatCap;
  if (shader == "ToonEnv" || shader == "ToonEnvOutlined") return ToonKind::Environment;
  throw Error("llvmpipe runner: material '" + m.name + "' uses toon shader '" + shader + "', which the runner lacks");
}

GLuint framebuffer(const std::vector<std::pair<GLenum, GLuint>>& attachments) {
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  for (const auto& [point, texture] : attachments) glFramebufferTexture2D(GL_FRAMEBUFFER, point, GL_TEXTURE_2D, texture, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("llvmpipe runner: incomplete cartoon framebuffer");
  }
  return fbo;
}

}  // namespace

GlCartoonFrame::GlCartoonFrame(const Scene& scene, GlScene& gl_scene, const CameraMatrices& camera,
                               const glm::dmat4& gl_view_projection, int width_px, int height_px)
    : gl_(gl_scene), camera_(camera), gl_view_projection_(gl_view_projection), width_px_(width_px),
      height_px_(height_px), lighting_(main_directional_light(scene)), library_(NormalEncoding::Unorm) {
  // ontile's toon materials (CartoonPipeline: ToonLook::PerMaterial, RGB10A2 normals), so the
  // shader choice, colours, bands, borders, textures and culling are the pipeline's own.
  renderers_ = make_scene_renderers(
      scene, [&](const Material& m) { return library_.make_material(m, ToonLook::PerMaterial); });
  for (const auto& material : renderers_.materials) {
    const PropertyBlock& p = material->properties;
    ToonMaterial m;
    m.key.kind = toon_kind(*material);
    const TextureBinding* base = p.get_texture("_BaseMap");
    m.key.base_map = base && base->texture && material->has_keyword("_BASEMAP");
    if (m.key.base_map) {
      m.base_map = gl_.texture(*base->texture);
      m.base_sampler = gl_.sampler(base->sampler);
    }
    // CelShader's parameters (toon_shaders.cpp cel_functors; a step size <= 0 means 1 / steps).
    m.steps = static_cast<int>(p.get_float("_Steps", 1.0f));
    m.step_size = p.get_float("_StepSize", 0.0f);
    if (m.steps < 1) throw Error("llvmpipe runner: material '" + material->name + "' has fewer than 1 cel step");
    if (!(m.step_size > 0.0f)) m.step_size = 1.0f / static_cast<float>(m.steps);
    m.lit_color = p.get_vector("_LitColor", glm::vec4(1.0f));
    m.shadow_color = p.get_vector("_ShadowColor", glm::vec4(0.5f));
    m.base_color = p.get_vector("_BaseColor", glm::vec4(1.0f));
    m.border_color = p.get_vector("_BorderColor");
    if (m.key.kind == ToonKind::MatCap) {
      const TextureBinding* normal = p.get_texture("_NormalMap");
      if (normal && normal->texture && material->has_keyword("_NORMALMAP")) {
        throw Error("llvmpipe runner: material '" + material->name + "' is a normal-mapped MatCap, which the runner lacks");
      }
      const TextureBinding* matcap = p.get_texture("_MatCap");
      if (!matcap || !matcap->texture) throw Error("llvmpipe runner: MatCap material '" + material->name + "' has no MatCap");
      m.matcap = gl_.texture(*matcap->texture);
      m.matcap_sampler = gl_.sampler(matcap_sampler());
    }
    if (m.key.kind == ToonKind::Environment && material->has_keyword("CAMERA_BASED_ENVIRONMENT")) {
      throw Error("llvmpipe runner: material '" + material->name + "' uses CAMERA_BASED_ENVIRONMENT, which the runner lacks");
    }
    m.state = material->state_for(*material->shader->find_light_mode(toon::kMrt));
    materials_[material.get()] = m;
  }
  const auto sky = generate_gradient_sky(kToonSkyFacePx);
  std::vector<const Texture2D*> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) faces.push_back(&sky->face(static_cast<CubeFace>(f)));
  environment_ = gl_.texture_array(faces);
  SamplerDesc face_sampler;  // CubeMap's: bilinear, base level, clamped inside the face
  face_sampler.mag_filter = face_sampler.min_filter = FilterMode::Linear;
  face_sampler.mipmap_mode = MipmapMode::None;
  face_sampler.wrap_u = face_sampler.wrap_v = WrapMode::ClampToEdge;
  environment_sampler_ = gl_.sampler(face_sampler);

  // FullScreenVertexShader(1, inverse view-projection): the view ray through each corner.
  const glm::dmat4 inverse_vp = glm::inverse(camera_.view_projection);
  const double corners[3][2] = {{-1.0, -1.0}, {3.0, -1.0}, {-1.0, 3.0}};
  for (int i = 0; i < 3; ++i) {
    const glm::dvec4 near_p = inverse_vp * glm::dvec4(corners[i][0], corners[i][1], 0.0, 1.0);
    const glm::dvec4 far_p = inverse_vp * glm::dvec4(corners[i][0], corners[i][1], 0.5, 1.0);
    sky_directions_[i] = glm::vec3(glm::dvec3(far_p) / far_p.w - glm::dvec3(near_p) / near_p.w);
  }

  auto target = [&](Target& t, GLenum internal_format) {
    t.internal_format = internal_format;
    glGenTextures(1, &t.texture);
    glBindTexture(GL_TEXTURE_2D, t.texture);
    glTexStorage2D(GL_TEXTURE_2D, 1, internal_format, width_px_, height_px_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  };
  target(color_, GL_SRGB8_ALPHA8);      // RGBA8_SRGB
  target(normals_, GL_RGB10_A2);        // RGB10A2_UNORM (the pipeline's default normals=rgb10a2)
  target(border_, GL_RGBA8);            // RGBA8_UNORM
  target(depth_, GL_DEPTH_COMPONENT32F);  // D32_FLOAT
  target(final_, GL_SRGB8_ALPHA8);
  target(mask_, GL_RGBA8);
  mrt_fbo_ = framebuffer({{GL_COLOR_ATTACHMENT0, color_.texture},
                          {GL_COLOR_ATTACHMENT1, normals_.texture},
                          {GL_COLOR_ATTACHMENT2, border_.texture},
                          {GL_DEPTH_ATTACHMENT, depth_.texture}});
  final_fbo_ = framebuffer({{GL_COLOR_ATTACHMENT0, final_.texture}});
  mask_fbo_ = framebuffer({{GL_COLOR_ATTACHMENT0, mask_.texture}});
  glGenVertexArrays(1, &empty_vao_);
  check_gl("cartoon set-up");
}

GlCartoonFrame::~GlCartoonFrame() {
  const GLuint fbos[] = {mrt_fbo_, final_fbo_, mask_fbo_};
  glDeleteFramebuffers(3, fbos);
  for (Target* t : {&color_, &normals_, &border_, &depth_, &final_, &mask_}) glDeleteTextures(1, &t->texture);
  glDeleteVertexArrays(1, &empty_vao_);
}

size_t GlCartoonFrame::render() {
  // Pass 1, "toon MRT": every target cleared (colour, normals and border to 0, depth to 1).
  glBindFramebuffer(GL_FRAMEBUFFER, mrt_fbo_);
  glDrawBuffers(3, kMrtBuffers);
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f}, far_depth = 1.0f;
  for (GLint i = 0; i < 3; ++i) glClearBufferfv(GL_COLOR, i, zero);
  glClearBufferfv(GL_DEPTH, 0, &far_depth);
  size_t draws = 0;
  draw_scene(draws);
  draw_sky();
  // Pass 2, "blit toon edges": the G-buffer as textures, into the final target.
  draw_edges(false);
  return draws;
}

void GlCartoonFrame::draw_scene(size_t& draws) {
  const GlToonProgram* bound = nullptr;
  // draw_renderers(culling, {{ToonMRT}, CommonOpaque}, all queues).
  for (uint32_t i : draw_order(renderers_.renderers, camera_, RenderQueueRange::all(), SortingCriteria::CommonOpaque)) {
    const Renderer& r = renderers_.renderers[i];
    const ToonMaterial& m = materials_.at(r.material);
    const GlToonProgram& program = programs_.toon(m.key);
    if (&program != bound) {
      glUseProgram(program.id);
      glUniform3fv(program.to_light, 1, &lighting_.to_light[0]);
      bound = &program;
    }
    // ToonVertexShader's matrices: products and inverses in double, rounded to float.
    const glm::mat4 mvp(gl_view_projection_ * r.world);
    const glm::mat3 normal_matrix(glm::transpose(glm::inverse(glm::dmat3(r.world))));
    const glm::mat3 view_normal_matrix(glm::transpose(glm::inverse(glm::dmat3(camera_.view * r.world))));
    glUniformMatrix4fv(program.mvp, 1, GL_FALSE, &mvp[0][0]);
    glUniformMatrix3fv(program.normal_matrix, 1, GL_FALSE, &normal_matrix[0][0]);
    glUniformMatrix3fv(program.view_normal_matrix, 1, GL_FALSE, &view_normal_matrix[0][0]);
    glUniform1i(program.steps, m.steps);
    glUniform1f(program.step_size, m.step_size);
    glUniform4fv(program.lit_color, 1, &m.lit_color[0]);
    glUniform4fv(program.shadow_color, 1, &m.shadow_color[0]);
    glUniform4fv(program.base_color, 1, &m.base_color[0]);
    glUniform4fv(program.border_color, 1, &m.border_color[0]);
    if (m.key.base_map) {
      glActiveTexture(GL_TEXTURE0 + kToonBaseMapUnit);
      glBindTexture(GL_TEXTURE_2D, m.base_map);
      glBindSampler(kToonBaseMapUnit, m.base_sampler);
    }
    if (m.key.kind == ToonKind::MatCap) {
      glActiveTexture(GL_TEXTURE0 + kToonMatCapUnit);
      glBindTexture(GL_TEXTURE_2D, m.matcap);
      glBindSampler(kToonMatCapUnit, m.matcap_sampler);
    }
    if (m.key.kind == ToonKind::Environment) {
      glActiveTexture(GL_TEXTURE0 + kToonEnvironmentUnit);
      glBindTexture(GL_TEXTURE_2D_ARRAY, environment_);
      glBindSampler(kToonEnvironmentUnit, environment_sampler_);
    }
    apply_cull(m.state.cull);
    apply_depth(m.state);
    apply_blend(m.state.blend);
    const GlScene::GlMesh& mesh = gl_.mesh(r.mesh);
    glBindVertexArray(mesh.vao);
    glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    ++draws;
  }
  glBindVertexArray(0);
}

void GlCartoonFrame::draw_sky() {
  // DrawSkybox: a full-screen triangle at depth 1, LessEqual without depth writes, no culling,
  // colour only (the other targets keep their clear values).
  glDrawBuffers(3, kColorOnly);
  const GlSkyProgram& sky = programs_.sky();
  glUseProgram(sky.id);
  glUniform3fv(sky.directions, 3, &sky_directions_[0][0]);
  glUniform3fv(sky.zenith, 1, &kSkyZenith[0]);
  glUniform3fv(sky.horizon, 1, &kSkyHorizon[0]);
  glUniform3fv(sky.ground, 1, &kSkyGround[0]);
  PassState state;
  state.cull = CullMode::None;
  state.depth_write = false;
  state.depth_compare = CompareOp::LessEqual;
  apply_cull(state.cull);
  apply_depth(state);
  apply_blend(state.blend);
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

void GlCartoonFrame::draw_edges(bool edge_mask) {
  glBindFramebuffer(GL_FRAMEBUFFER, edge_mask ? mask_fbo_ : final_fbo_);
  glDrawBuffers(1, kMrtBuffers);
  const GlEdgeProgram& program = programs_.edges(edge_mask);
  glUseProgram(program.id);
  // The edge material's parameters (toon_shaders.cpp): SobelEdgeParams' defaults with the
  // camera's depth range and view rays.
  const SobelEdgeParams defaults;
  const DepthLinearization linearization = DepthLinearization::from_projection(camera_.projection);
  const glm::vec2 ray_scale = view_ray_scale(camera_.projection);
  glUniform2f(program.tap_step, defaults.thickness_px / static_cast<float>(width_px_),
              defaults.thickness_px / static_cast<float>(height_px_));
  glUniform1i(program.orthographic, linearization.orthographic ? 1 : 0);
  glUniform1f(program.near_plane, linearization.near_plane);
  glUniform1f(program.far_plane, linearization.far_plane);
  glUniform2f(program.view_ray_scale, ray_scale.x, ray_scale.y);
  glUniform1f(program.depth_limit_scale, defaults.depth_threshold * defaults.depth_sensitivity);
  glUniform1f(program.normal_threshold, defaults.normal_threshold);
  glUniform1f(program.min_grazing_cosine, defaults.min_grazing_cosine);
  const std::pair<GLint, GLuint> inputs[] = {{kEdgeColorUnit, color_.texture},
                                             {kEdgeDepthUnit, depth_.texture},
                                             {kEdgeNormalUnit, normals_.texture},
                                             {kEdgeBorderUnit, border_.texture}};
  for (const auto& [unit, texture] : inputs) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindSampler(unit, 0);  // the targets' own nearest, single-level state
  }
  PassState state;  // the full-screen edge pass: no culling, no depth
  state.cull = CullMode::None;
  state.depth_test = false;
  state.depth_write = false;
  apply_cull(state.cull);
  apply_depth(state);
  apply_blend(state.blend);
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

std::vector<uint8_t> GlCartoonFrame::read_color() const {
  std::vector<uint8_t> rgba(static_cast<size_t>(width_px_) * height_px_ * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, final_fbo_);
  glReadPixels(0, 0, width_px_, height_px_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  check_gl("reading the cartoon colour");
  return rgba;
}

std::vector<uint8_t> GlCartoonFrame::edge_mask() {
  draw_edges(true);
  std::vector<uint8_t> rgba(static_cast<size_t>(width_px_) * height_px_ * 4);
  glReadPixels(0, 0, width_px_, height_px_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  check_gl("the edge-mask pass");
  std::vector<uint8_t> mask(rgba.size() / 4);
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = rgba[i * 4];
  return mask;
}

}  // namespace ontile::peer
