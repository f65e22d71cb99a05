// Reference shading with the lambert pipeline's functors (see reference_shading.h).
#include "reference/reference_shading.h"

#include <algorithm>

#include "pipelines/lit/lit_shader.h"
#include "util/error.h"

namespace ontile {

LambertReferenceScene make_lambert_reference_scene(const Scene& scene, const Camera& camera,
                                                   int width_px, int height_px) {
  LambertReferenceScene ref;
  ref.camera = camera_matrices(camera, double(width_px) / height_px);
  ref.clear_color = lit::kBackgroundColor;
  ref.lit_shader = make_lit_shader();
  const Shader& lit = *ref.lit_shader;
  ref.renderers = make_scene_renderers(scene, [&](const Material& m) { return make_lit_material(lit, m); });
  const ShaderPass* pass = lit.find_light_mode(lit::kForwardLit);
  if (!pass) throw Error("reference renderer: the Lit shader has no ForwardLit pass");
  const PropertyBlock globals = lighting_globals(main_directional_light(scene));

  std::vector<CullMode> cull_modes;
  for (const Renderer& r : ref.renderers.renderers) {
    // The DrawContext FrameExecutor::draw_with_pass builds: globals, then shader defaults,
    // then material values.
    DrawContext ctx;
    ctx.mesh = r.mesh;
    ctx.world = r.world;
    ctx.camera = ref.camera;
    ctx.material = r.material;
    ctx.properties = globals;
    ctx.properties.merge_from(r.material->shader->defaults);
    ctx.properties.merge_from(r.material->properties);
    ctx.target_width_px = width_px;
    ctx.target_height_px = height_px;
    ctx.resolve_texture = [&](const TextureBinding&) -> std::shared_ptr<const Texture2D> {
      throw Error("reference renderer: material '" + r.material->name +
                  "' samples a render target, which the lambert pipeline never binds");
    };
    ReferenceDraw draw;
    draw.functors = pass->factory(ctx);
    if (!draw.functors.vertex || !draw.functors.fragment) {
      throw Error("reference renderer: material '" + r.material->name + "' built no vertex or fragment functor");
    }
    if (draw.functors.vertex->varying_count() < MeshVertexShader::kNormal + 3) {
      throw Error("reference renderer: material '" + r.material->name + "' has no normal varyings");
    }
    draw.state = r.material->state_for(*pass);
    // lambert draws RenderQueueRange::opaque() first, then transparent().
    if (r.material->render_queue > RenderQueueRange::opaque().upper) {
      draw.surface_class = SurfaceClass::Blended;
    } else {
      draw.surface_class = draw.functors.fragment->may_discard() ? SurfaceClass::AlphaTested : SurfaceClass::Opaque;
    }
    cull_modes.push_back(draw.state.cull);
    ref.draws.push_back(std::move(draw));
  }
  ref.geometry = std::make_unique<ReferenceGeometry>(ref.renderers.renderers, cull_modes);
  return ref;
}

void shade_hit_quad(const LambertReferenceScene& ref, const RayCandidate& hit, const QuadRays& rays,
                    int quad_x_px, int quad_y_px, uint8_t lane_mask, QuadShading& out) {
  const ReferenceDraw& draw = ref.draws[hit.renderer];
  const VertexShader& vs = *draw.functors.vertex;
  const int n = vs.varying_count();
  const std::array<uint32_t, 3> index = ref.geometry->triangle_indices(hit.renderer, hit.triangle);
  const std::array<glm::dvec3, 3> p = ref.geometry->triangle_world(hit.renderer, hit.triangle);
  glm::vec4 clip[3];
  float vertex_varyings[3][kMaxVaryings];
  for (int i = 0; i < 3; ++i) vs.shade(index[i], 1, &clip[i], vertex_varyings[i]);

  QuadFragment quad;
  quad.x_px = quad_x_px;
  quad.y_px = quad_y_px;
  quad.lane_mask = lane_mask;
  quad.front_facing = hit.front_facing;
  quad.primitive_id = hit.primitive_id;
  quad.sample = -1;
  for (int k = 0; k < kMaxVaryings; ++k) std::fill_n(quad.varyings[k], kQuadLanes, 0.0f);
  const glm::dvec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double inv_normal_length2 = 1.0 / glm::dot(normal, normal);
  bool on_plane[kQuadLanes];
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    // Every lane, helper or not, takes its ray's intersection with the triangle's plane: the
    // perspective-correct extrapolation a rasterizer's helper lanes get in screen space.
    const double n_dot_d = glm::dot(normal, rays.direction[lane]);
    on_plane[lane] = n_dot_d != 0.0;
    if (!on_plane[lane]) continue;
    const double t = glm::dot(normal, p[0] - rays.origin[lane]) / n_dot_d;
    const glm::dvec3 x = rays.origin[lane] + t * rays.direction[lane];
    // Barycentrics as ratios of signed sub-triangle areas (projected on the normal).
    const double b0 = glm::dot(normal, glm::cross(p[2] - p[1], x - p[1])) * inv_normal_length2;
    const double b1 = glm::dot(normal, glm::cross(p[0] - p[2], x - p[2])) * inv_normal_length2;
    const double b2 = 1.0 - b0 - b1;
    for (int k = 0; k < n; ++k) {
      quad.varyings[k][lane] = static_cast<float>(b0 * vertex_varyings[0][k] + b1 * vertex_varyings[1][k] +
                                                  b2 * vertex_varyings[2][k]);
    }
    const glm::dvec4 x_clip = ref.camera.view_projection * glm::dvec4(x, 1.0);
    quad.depth[lane] = static_cast<float>(std::clamp(x_clip.z / x_clip.w, 0.0, 1.0));
  }
  // A helper ray parallel to the plane has no intersection: it repeats the hit lane's values,
  // giving a zero derivative along that direction instead of an infinite one.
  int source = 0;
  while (source < kQuadLanes && !(on_plane[source] && ((lane_mask >> source) & 1u))) ++source;
  if (source == kQuadLanes) throw Error("reference renderer: shaded a quad whose active lanes miss the plane");
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (on_plane[lane]) continue;
    for (int k = 0; k < n; ++k) quad.varyings[k][lane] = quad.varyings[k][source];
    quad.depth[lane] = quad.depth[source];
  }

  for (int lane = 0; lane < kQuadLanes; ++lane) out.output.color[0][lane] = glm::vec4(0.0f);
  out.output.discard_mask = 0;
  draw.functors.fragment->shade(quad, out.output);
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    out.depth[lane] = quad.depth[lane];
    // The normal the Lambert functor shades with: normalised, flipped on back faces.
    glm::vec3 nv = quad.var3(MeshVertexShader::kNormal, lane);
    const float len = glm::length(nv);
    nv = len > 0.0f ? nv / len : glm::vec3(0.0f, 0.0f, 1.0f);
    out.normal[lane] = hit.front_facing ? nv : -nv;
  }
}

}  // namespace ontile
