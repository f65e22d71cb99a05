// The cartoon pipelines (see cartoon_pipelines.h).
#include "pipelines/cartoon/cartoon_pipelines.h"

#include "context/render_graph.h"
#include "context/scene_renderers.h"
#include "pipelines/cartoon/toon_shaders.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr glm::vec4 kNoClear(0.0f);

NormalEncoding normal_format_option(const FrameInputs& in, PixelFormat& format) {
  const std::string normals = in.options.take("normals", "rgb10a2");
  if (normals == "rgb10a2") {
    format = PixelFormat::RGB10A2_UNORM;
    return NormalEncoding::Unorm;
  }
  if (normals == "rgba16f") {
    format = PixelFormat::RGBA16_FLOAT;
    return NormalEncoding::Float;
  }
  throw Error("pipeline option normals='" + normals + "': expected rgb10a2 or rgba16f");
}

AttachmentDesc target(const char* name, Surface* s, LoadAction load, StoreAction store,
                      glm::vec4 clear = kNoClear) {
  return {name, s ? s->format() : PixelFormat::D32_FLOAT, load, store, clear, s, nullptr};
}

AttachmentDesc transient_depth() {
  return {"depth", PixelFormat::D32_FLOAT, LoadAction::Clear, StoreAction::DontCare,
          glm::vec4(1.0f), nullptr, nullptr};
}

// cartoon-multipass as a render graph: the scene drawn once per buffer, each pass with its
// own (transient) depth test, then the Sobel edges sample every buffer's neighbours.
FrameOutputs render_multipass(RenderContext& ctx, const FrameInputs& in, const ToonShaderLibrary& library,
                              const CullingResults& culling, const CameraMatrices& camera, PixelFormat normal_format) {
  RenderGraph graph;
  auto target = [&](const char* name, PixelFormat format, glm::vec4 clear = kNoClear, bool memoryless = false) {
    return graph.create({name, format, in.width_px, in.height_px, 1, clear, {}, memoryless});
  };
  const GraphResource color = target("color", PixelFormat::RGBA8_SRGB);
  const GraphResource normals = target("normals", normal_format);
  const GraphResource border = target("border", PixelFormat::RGBA8_UNORM);
  const GraphResource depth = target("depth", PixelFormat::D32_FLOAT, glm::vec4(1.0f));
  const GraphResource final_image = target("final", PixelFormat::RGBA8_SRGB);
  struct Step { const char* pass; GraphResource output; const char* light_mode; };
  for (const Step& s : {Step{"toon colour", color, toon::kColor}, Step{"toon normals", normals, toon::kNormal},
                        Step{"toon border", border, toon::kBorder}}) {
    graph.add_pass(s.pass)
        .write_color(s.output, LoadAction::Clear, StoreAction::Store)
        .write_depth(target("depth", PixelFormat::D32_FLOAT, glm::vec4(1.0f), true), LoadAction::Clear,
                     StoreAction::DontCare)
        .record([&, s](GraphPassRecorder& r) {
          r.draw_renderers(culling, {{s.light_mode}, SortingCriteria::CommonOpaque}, {RenderQueueRange::all()});
          if (s.output.index == color.index) r.draw_skybox(camera);
        });
  }
  graph.add_pass("toon depth").write_depth(depth, LoadAction::Clear, StoreAction::Store).record([&](GraphPassRecorder& r) {
    r.draw_renderers(culling, {{toon::kDepthOnly}, SortingCriteria::CommonOpaque}, {RenderQueueRange::all()});
  });
  // Screen-space edges: Sobel on depth and normals (3x3 neighbours, so texture reads),
  // coloured by the border buffer; named as CommandBuffer::blit names its pass.
  graph.add_pass("blit " + library.edges_material().name)
      .read_texture(color).read_texture(depth).read_texture(normals).read_texture(border)
      .write_color(final_image, LoadAction::DontCare, StoreAction::Store)
      .record([&](GraphPassRecorder& r) {
        r.set_global_texture("_DepthTex", r.texture(depth));
        r.set_global_texture("_NormalTex", r.texture(normals));
        r.set_global_texture("_BorderTex", r.texture(border));
        r.blit_from(color, &library.edges_material(), toon::kEdgesPass);
      });
  graph.mark_output(final_image);
  graph.execute(ctx);
  FrameOutputs out;
  out.report = ctx.submit();
  out.color = graph.surface(final_image);
  return out;
}

}  // namespace

FrameOutputs CartoonPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  PixelFormat normal_format;
  const NormalEncoding encoding = normal_format_option(in, normal_format);
  in.options.reject_unknown(name());
  const Scene& scene = *in.scene;
  const CameraMatrices camera = camera_matrices(in.camera, double(in.width_px) / in.height_px);
  const ToonShaderLibrary library(encoding);
  const SceneRenderers sr = make_scene_renderers(
      scene, [&](const Material& m) { return library.make_material(m, ToonLook::PerMaterial); });
  const CullingResults culling = ctx.cull(sr.renderers, camera);
  set_toon_globals(ctx, scene, in.camera, camera);

  if (multipass_) return render_multipass(ctx, in, library, culling, camera, normal_format);
  const int w = in.width_px, h = in.height_px;
  Surface* color = ctx.create_surface("color", PixelFormat::RGBA8_SRGB, w, h);
  Surface* normals = ctx.create_surface("normals", normal_format, w, h);
  Surface* border = ctx.create_surface("border", PixelFormat::RGBA8_UNORM, w, h);
  Surface* depth = ctx.create_surface("depth", PixelFormat::D32_FLOAT, w, h);
  Surface* final_image = ctx.create_surface("final", PixelFormat::RGBA8_SRGB, w, h);

  // The paper's design: every G-buffer target written by one MRT pass; the sky writes colour
  // only (the other outputs stay zero, as their clears).
  ctx.begin_render_pass("toon MRT", w, h, 1,
                        {target("color", color, LoadAction::Clear, StoreAction::Store),
                         target("normals", normals, LoadAction::Clear, StoreAction::Store),
                         target("border", border, LoadAction::Clear, StoreAction::Store),
                         target("depth", depth, LoadAction::Clear, StoreAction::Store, glm::vec4(1.0f))},
                        3);
  ctx.begin_subpass({0, 1, 2});
  ctx.draw_renderers(culling, {{toon::kMrt}, SortingCriteria::CommonOpaque}, {RenderQueueRange::all()});
  ctx.draw_skybox(camera);
  ctx.end_subpass();
  ctx.end_render_pass();

  // Screen-space edges: Sobel on depth and normals, coloured by the border buffer.
  CommandBuffer cmd("toon edges");
  cmd.set_global_texture("_DepthTex", {nullptr, RenderTargetRef::of(depth), {}});
  cmd.set_global_texture("_NormalTex", {nullptr, RenderTargetRef::of(normals), {}});
  cmd.set_global_texture("_BorderTex", {nullptr, RenderTargetRef::of(border), {}});
  cmd.blit(RenderTargetRef::of(color), RenderTargetRef::of(final_image), &library.edges_material(),
           toon::kEdgesPass);
  ctx.execute_command_buffer(cmd);

  FrameOutputs out;
  out.report = ctx.submit();
  out.color = final_image;
  return out;
}

FrameOutputs CartoonHullPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  in.options.reject_unknown(name());
  const Scene& scene = *in.scene;
  const CameraMatrices camera = camera_matrices(in.camera, double(in.width_px) / in.height_px);
  const ToonShaderLibrary library(NormalEncoding::Unorm);
  const SceneRenderers sr = make_scene_renderers(
      scene, [&](const Material& m) { return library.make_material(m, ToonLook::Environment); });
  const CullingResults culling = ctx.cull(sr.renderers, camera);
  set_toon_globals(ctx, scene, in.camera, camera);

  Surface* color = ctx.create_surface("color", PixelFormat::RGBA8_SRGB, in.width_px, in.height_px);
  ctx.begin_render_pass("toon forward + hull outlines", in.width_px, in.height_px, 1,
                        {target("color", color, LoadAction::Clear, StoreAction::Store), transient_depth()}, 1);
  ctx.begin_subpass({0});
  ctx.draw_renderers(culling, {{toon::kColor}, SortingCriteria::CommonOpaque}, {RenderQueueRange::all()});
  ctx.draw_skybox(camera);
  // Inverted hulls after the shaded surfaces: front faces culled, so only the rim around each
  // object survives the depth test.
  ctx.draw_renderers(culling, {{toon::kOutline}, SortingCriteria::CommonOpaque}, {RenderQueueRange::all()});
  ctx.end_subpass();
  ctx.end_render_pass();

  FrameOutputs out;
  out.report = ctx.submit();
  out.color = color;
  return out;
}

}  // namespace ontile
