// The cartoon frame rebuilt with an edge-mask output (see cartoon_reference.h). The passes
// below follow CartoonPipeline::render (src/pipelines/cartoon/cartoon_pipelines.cpp) and the
// edge material's factory (toon_shaders.cpp) line for line.
#include "cartoon_reference.h"

#include "context/attachment.h"
#include "context/camera_matrices.h"
#include "context/scene_renderers.h"
#include "pipelines/cartoon/toon_shaders.h"
#include "raster/raster_types.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/toon/sobel_edge_shader.h"
#include "util/error.h"

namespace ontile::peer {
namespace {

// The edge material with the scene colour replaced by black and the border by opaque white:
// SobelEdgeShader then writes mix(0, 1, edge) = 1 on an edge and 0 elsewhere.
std::unique_ptr<Shader> edge_mask_shader(const Texture2D* black) {
  auto shader = std::make_unique<Shader>("ToonEdgeMask");
  PassState full_screen;
  full_screen.cull = CullMode::None;
  full_screen.depth_test = false;
  full_screen.depth_write = false;
  shader->add_pass({toon::kEdgesPass, "", full_screen, [black](const DrawContext& c) {
                      DrawFunctors f;
                      f.vertex = std::make_unique<FullScreenVertexShader>();
                      SobelEdgeParams p;
                      p.depth_linearization = DepthLinearization::from_projection(c.camera.projection);
                      p.view_ray_scale = view_ray_scale(c.camera.projection);
                      p.normal_encoding = NormalEncoding::Unorm;
                      const auto depth = c.texture("_DepthTex");
                      const auto normal = c.texture("_NormalTex");
                      p.color = black;
                      p.depth = depth.get();
                      p.normal = normal.get();
                      p.border = nullptr;
                      p.default_border_color = glm::vec4(1.0f);
                      f.fragment = std::make_unique<SobelEdgeShader>(p);
                      return f;
                    }});
  return shader;
}

}  // namespace

CartoonReference render_cartoon_reference(const Scene& scene, const RenderSettings& settings) {
  const int w = settings.width_px, h = settings.height_px;
  if (w <= 0 || h <= 0 || w > kMaxTargetSizePx || h > kMaxTargetSizePx) {
    throw Error("cartoon reference: image size " + std::to_string(w) + "x" + std::to_string(h) + " out of range");
  }
  const Camera camera = select_camera(scene, settings.camera_index);
  RenderContext ctx(settings.context);
  const CameraMatrices matrices = camera_matrices(camera, double(w) / h);
  const ToonShaderLibrary library(NormalEncoding::Unorm);
  const SceneRenderers sr = make_scene_renderers(
      scene, [&](const Material& m) { return library.make_material(m, ToonLook::PerMaterial); });
  const CullingResults culling = ctx.cull(sr.renderers, matrices);
  set_toon_globals(ctx, scene, camera, matrices);

  Surface* color = ctx.create_surface("color", PixelFormat::RGBA8_SRGB, w, h);
  Surface* normals = ctx.create_surface("normals", PixelFormat::RGB10A2_UNORM, w, h);
  Surface* border = ctx.create_surface("border", PixelFormat::RGBA8_UNORM, w, h);
  Surface* depth = ctx.create_surface("depth", PixelFormat::D32_FLOAT, w, h);
  Surface* final_image = ctx.create_surface("final", PixelFormat::RGBA8_SRGB, w, h);
  Surface* mask = ctx.create_surface("edge mask", PixelFormat::RGBA8_UNORM, w, h);

  ctx.begin_render_pass("toon MRT", w, h, 1,
                        {Attachment::stored("color", color).clear(glm::vec4(0.0f)),
                         Attachment::stored("normals", normals).clear(glm::vec4(0.0f)),
                         Attachment::stored("border", border).clear(glm::vec4(0.0f)),
                         Attachment::stored("depth", depth).clear_depth(1.0f)},
                        3);
  ctx.begin_subpass({0, 1, 2});
  ctx.draw_renderers(culling, {{toon::kMrt}, SortingCriteria::CommonOpaque}, {RenderQueueRange::all()});
  ctx.draw_skybox(matrices);
  ctx.end_subpass();
  ctx.end_render_pass();

  const auto black = Texture2D::from_rgba8(w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4, 0),
                                           /*srgb=*/false, "black");
  const std::unique_ptr<Shader> mask_shader = edge_mask_shader(black.get());
  const RenderMaterial mask_material("toon edge mask", mask_shader.get());
  CommandBuffer cmd("toon edges");
  cmd.set_global_texture("_DepthTex", {nullptr, RenderTargetRef::of(depth), {}});
  cmd.set_global_texture("_NormalTex", {nullptr, RenderTargetRef::of(normals), {}});
  cmd.set_global_texture("_BorderTex", {nullptr, RenderTargetRef::of(border), {}});
  cmd.blit(RenderTargetRef::of(color), RenderTargetRef::of(final_image), &library.edges_material(),
           toon::kEdgesPass);
  cmd.blit(RenderTargetRef::of(color), RenderTargetRef::of(mask), &mask_material, toon::kEdgesPass);
  ctx.execute_command_buffer(cmd);
  ctx.submit();

  CartoonReference out;
  out.final_rgba = final_image->bytes();
  out.edge_mask.resize(static_cast<size_t>(w) * h);
  const std::vector<uint8_t>& m = mask->bytes();
  for (size_t i = 0; i < out.edge_mask.size(); ++i) out.edge_mask[i] = m[i * 4] != 0;
  return out;
}

}  // namespace ontile::peer
