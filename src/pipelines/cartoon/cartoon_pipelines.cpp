// The cartoon pipelines (see cartoon_pipelines.h).
#include "pipelines/cartoon/cartoon_pipelines.h"

#include "pipelines/cartoon/toon_shaders.h"
#include "pipelines/kit/pipeline_api.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr glm::vec4 kNoClear(0.0f);

NormalEncoding normal_format_option(const PipelineOptions& options, PixelFormat& format) {
  const std::string normals = options.take("normals", "rgb10a2");
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

// cartoon-multipass as a render graph: the scene drawn once per buffer, each pass with its
// own (transient) depth test, then the Sobel edges sample every buffer's neighbours.
FrameOutputs render_multipass(const FrameKit& kit, const ToonShaderLibrary& library, PixelFormat normal_format) {
  RenderGraph graph;
  auto target = [&](const char* name, PixelFormat format, glm::vec4 clear = kNoClear, bool memoryless = false) {
    return graph.create({name, format, kit.width_px(), kit.height_px(), 1, clear, {}, memoryless});
  };
  const CullingResults& culling = kit.culling();
  const CameraMatrices& camera = kit.matrices();
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
  return kit.submit(graph, final_image);
}

}  // namespace

FrameOutputs CartoonPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  PixelFormat normal_format;
  const NormalEncoding encoding =
      read_options(in, name(), [&](const PipelineOptions& o) { return normal_format_option(o, normal_format); });
  const ToonShaderLibrary library(encoding);
  FrameKit kit(ctx, in);
  const CullingResults& culling =
      kit.cull([&](const Material& m) { return library.make_material(m, ToonLook::PerMaterial); });
  const CameraMatrices& camera = kit.matrices();
  set_toon_globals(ctx, kit.scene(), in.camera, camera);

  if (multipass_) return render_multipass(kit, library, normal_format);
  Surface* color = kit.create_target("color", PixelFormat::RGBA8_SRGB);
  Surface* normals = kit.create_target("normals", normal_format);
  Surface* border = kit.create_target("border", PixelFormat::RGBA8_UNORM);
  Surface* depth = kit.create_target("depth", PixelFormat::D32_FLOAT);
  Surface* final_image = kit.create_target("final", PixelFormat::RGBA8_SRGB);

  // The paper's design: every G-buffer target written by one MRT pass; the sky writes colour
  // only (the other outputs stay zero, as their clears).
  ctx.begin_render_pass("toon MRT", in.width_px, in.height_px, 1,
                        {Attachment::stored("color", color).clear(kNoClear),
                         Attachment::stored("normals", normals).clear(kNoClear),
                         Attachment::stored("border", border).clear(kNoClear),
                         Attachment::stored("depth", depth).clear_depth(1.0f)},
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
  return kit.submit(final_image);
}

FrameOutputs CartoonHullPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  in.options.reject_unknown(name());
  const ToonShaderLibrary library(NormalEncoding::Unorm);
  FrameKit kit(ctx, in);
  const CullingResults& culling =
      kit.cull([&](const Material& m) { return library.make_material(m, ToonLook::Environment); });
  const CameraMatrices& camera = kit.matrices();
  set_toon_globals(ctx, kit.scene(), in.camera, camera);

  Surface* color = kit.create_target("color", PixelFormat::RGBA8_SRGB);
  ctx.begin_render_pass("toon forward + hull outlines", in.width_px, in.height_px, 1,
                        {Attachment::stored("color", color).clear(kNoClear),
                         Attachment::transient("depth", PixelFormat::D32_FLOAT).clear_depth(1.0f)},
                        1);
  ctx.begin_subpass({0});
  ctx.draw_renderers(culling, {{toon::kColor}, SortingCriteria::CommonOpaque}, {RenderQueueRange::all()});
  ctx.draw_skybox(camera);
  // Inverted hulls after the shaded surfaces: front faces culled, so only the rim around each
  // object survives the depth test.
  ctx.draw_renderers(culling, {{toon::kOutline}, SortingCriteria::CommonOpaque}, {RenderQueueRange::all()});
  ctx.end_subpass();
  ctx.end_render_pass();
  return kit.submit(color);
}

namespace {
const PipelineRegistration kCartoon("cartoon", [] { return std::make_unique<CartoonPipeline>(false); });
const PipelineRegistration kCartoonMultipass("cartoon-multipass",
                                             [] { return std::make_unique<CartoonPipeline>(true); });
const PipelineRegistration kCartoonHull("cartoon-hull", [] { return std::make_unique<CartoonHullPipeline>(); });
}  // namespace

}  // namespace ontile
