// The deferred pipelines and the forward baseline (see deferred_pipelines.h).
#include "pipelines/deferred/deferred_pipelines.h"

#include "pipelines/deferred/deferred_options.h"
#include "pipelines/deferred/deferred_shaders.h"
#include "pipelines/deferred/scene_lighting_setup.h"
#include "pipelines/kit/pipeline_api.h"
#include "pipelines/lit/lit_shader.h"

namespace ontile {
namespace {


// What every variant prepares before recording: the kit's camera and culling, lights and
// shaders. Built in place (the shader library points to the lighting), alive until submit().
struct FrameSetup {
  FrameSetup(const FrameInputs& in, const DeferredOptions& options, RenderContext& ctx)
      : kit(ctx, in),
        lighting(make_scene_lighting(*in.scene, options.generated_lights, kit.matrices(), in.width_px, in.height_px)),
        library(options.layout, lighting, kit.matrices(), in.width_px, in.height_px),
        culling(kit.cull([&](const Material& m) { return library.make_material(m); })) {
    for (uint32_t i : culling.visible) {
      if (kit.renderers().renderers[i].material->render_queue > RenderQueueRange::opaque().upper) {
        has_transparent = true;
      }
    }
  }
  FrameKit kit;
  SceneLighting lighting;
  DeferredShaderLibrary library;
  const CullingResults& culling;
  bool has_transparent = false;
};

void draw_opaque(RenderContext& ctx, const FrameSetup& s, const char* light_mode) {
  ctx.draw_renderers(s.culling, {{light_mode}, SortingCriteria::CommonOpaque}, {RenderQueueRange::opaque()});
}

void draw_transparent(RenderContext& ctx, const FrameSetup& s) {
  ctx.draw_renderers(s.culling, {{deferred::kForwardLit}, SortingCriteria::CommonTransparent},
                     {RenderQueueRange::transparent()});
}

// deferred-classic as a render graph written pass by pass, the way the two-pass renderer is
// (docs/render-graph.md): the G-buffer pass stores every target and depth, lighting reads them
// at its own pixel (textures unless --render-graph merge puts both in one render pass).
FrameOutputs render_classic(const FrameInputs& in, const DeferredOptions& options, const FrameSetup& setup) {
  const GBufferLayout& layout = options.layout;
  const int w = in.width_px, h = in.height_px;
  const std::vector<PixelFormat> formats = layout.target_formats();
  const std::vector<std::string> names = layout.target_names();
  const int targets = layout.target_count();
  RenderGraph graph;
  auto target = [&](const std::string& name, PixelFormat format, glm::vec4 clear = glm::vec4(0.0f)) {
    return graph.create({name, format, w, h, 1, clear});
  };
  const GraphResource light = target("light", layout.light_format, lit::kBackgroundColor);
  const GraphResource depth = target("depth", layout.depth_format, glm::vec4(1.0f));
  std::vector<GraphResource> gbuffer;
  for (int k = 0; k < targets; ++k) gbuffer.push_back(target(names[k], formats[k]));
  const GraphResource final_image = options.tonemap ? target("final", PixelFormat::RGBA8_SRGB) : GraphResource{};

  GraphPassBuilder gbuffer_pass = graph.add_pass("gbuffer");
  if (layout.light_in_gbuffer) gbuffer_pass.write_color(light, LoadAction::Clear, StoreAction::Store);
  for (int k = 0; k < targets; ++k) gbuffer_pass.write_color(gbuffer[k], LoadAction::Clear, StoreAction::Store);
  gbuffer_pass.write_depth(depth, LoadAction::Clear, StoreAction::Store).record([&](GraphPassRecorder& r) {
    r.draw_renderers(setup.culling, {{deferred::kGBuffer}, SortingCriteria::CommonOpaque}, {RenderQueueRange::opaque()});
  });

  // Unity's lighting pass loads the accumulation the G-buffer pass started; Vulkan-Samples'
  // clears the light target. Input k of the on-tile shader is depth, then the G-buffer.
  const LoadAction light_load = layout.light_in_gbuffer ? LoadAction::Load : LoadAction::Clear;
  GraphPassBuilder lighting = graph.add_pass("lighting");
  lighting.write_color(light, light_load, StoreAction::Store).read_own_pixel(depth);
  for (int k = 0; k < targets; ++k) lighting.read_own_pixel(gbuffer[k]);
  lighting.record([&](GraphPassRecorder& r) {
    const bool from_textures = !r.on_tile(depth);
    if (from_textures) {
      r.set_global_texture(deferred::kDepthTexture, r.texture(depth));
      for (int k = 0; k < targets; ++k) r.set_global_texture(deferred::gbuffer_texture(k), r.texture(gbuffer[k]));
    }
    r.draw_full_screen(&setup.library.lighting_material(from_textures), deferred::kLightingPass);
  });

  if (setup.has_transparent) {
    graph.add_pass("transparent")
        .write_color(light, LoadAction::Load, StoreAction::Store)
        .read_depth(depth, LoadAction::Load, StoreAction::DontCare)
        .record([&](GraphPassRecorder& r) {
          r.draw_renderers(setup.culling, {{deferred::kForwardLit}, SortingCriteria::CommonTransparent},
                           {RenderQueueRange::transparent()});
        });
  }
  if (options.tonemap) {
    graph.add_pass("tonemap")
        .read_own_pixel(light)
        .write_color(final_image, LoadAction::DontCare, StoreAction::Store)
        .record([&](GraphPassRecorder& r) {
          const bool from_textures = !r.on_tile(light);
          if (from_textures) r.set_global_texture(deferred::kLightTexture, r.texture(light));
          r.draw_full_screen(&setup.library.tonemap_material(from_textures), deferred::kTonemapPass);
        });
  }
  return setup.kit.submit(graph, options.tonemap ? final_image : light);
}

// The subpasses after the G-buffer, in the render pass that holds it: lighting from depth and
// the G-buffer as input attachments into the light target (attachment 0), the transparent
// objects forward on top, and the tonemap of an HDR light target into `final_index`.
void record_on_tile_lighting(RenderContext& ctx, const FrameSetup& setup, bool tonemap,
                             const std::vector<int>& lighting_inputs, int final_index) {
  ctx.begin_subpass({0}, lighting_inputs, true);
  ctx.draw_full_screen(&setup.library.lighting_material(false), deferred::kLightingPass);
  ctx.end_subpass();
  if (setup.has_transparent) {
    ctx.begin_subpass({0}, {}, true);
    draw_transparent(ctx, setup);
    ctx.end_subpass();
  }
  if (tonemap) {
    ctx.begin_subpass({final_index}, {0}, true);
    ctx.draw_full_screen(&setup.library.tonemap_material(false), deferred::kTonemapPass);
    ctx.end_subpass();
  }
}

// Vulkan-Samples' subpasses sample with "render technique: two render passes"
// (Subpasses::draw_renderpasses): the geometry pass clears and stores every attachment of the
// render target, the light target included (gbuffer::get_clear_store_all); the lighting pass
// loads them all (get_load_all_store_swapchain), reads depth and the G-buffer as input
// attachments and stores only the light target. Unlike deferred-classic nothing is sampled as a
// texture: the G-buffer comes back as tile loads, which AFBC prices compressed.
FrameOutputs render_two_render_passes(RenderContext& ctx, const FrameInputs& in, const DeferredOptions& options,
                                      const FrameSetup& setup) {
  const GBufferLayout& layout = options.layout;
  const int w = in.width_px, h = in.height_px;
  const std::vector<PixelFormat> formats = layout.target_formats();
  const std::vector<std::string> names = layout.target_names();
  const int targets = layout.target_count();
  Surface* light = setup.kit.create_target("light", layout.light_format);
  Surface* depth = setup.kit.create_target("depth", layout.depth_format);
  Surface* final_image = options.tonemap ? setup.kit.create_target("final", PixelFormat::RGBA8_SRGB) : nullptr;
  std::vector<Surface*> gbuffer;
  for (int k = 0; k < targets; ++k) gbuffer.push_back(setup.kit.create_target(names[k], formats[k]));

  std::vector<AttachmentDesc> written = {Attachment::stored("light", light).clear(lit::kBackgroundColor),
                                         Attachment::stored("depth", depth).clear_depth(1.0f)};
  std::vector<int> gbuffer_outputs, lighting_inputs{1};
  if (layout.light_in_gbuffer) gbuffer_outputs.push_back(0);
  for (int k = 0; k < targets; ++k) {
    gbuffer_outputs.push_back(static_cast<int>(written.size()));
    lighting_inputs.push_back(static_cast<int>(written.size()));
    written.push_back(Attachment::stored(names[k], gbuffer[k]).clear(glm::vec4(0.0f)));
  }
  ctx.begin_render_pass("gbuffer", w, h, 1, written, 1);
  ctx.begin_subpass(gbuffer_outputs);
  draw_opaque(ctx, setup, deferred::kGBuffer);
  ctx.end_subpass();
  ctx.end_render_pass();

  std::vector<AttachmentDesc> loaded = {
      options.tonemap ? Attachment::stored("light", light).load().discard() : Attachment::stored("light", light).load(),
      Attachment::stored("depth", depth).load().discard()};
  for (int k = 0; k < targets; ++k) loaded.push_back(Attachment::stored(names[k], gbuffer[k]).load().discard());
  const int final_index = static_cast<int>(loaded.size());
  if (options.tonemap) loaded.push_back(Attachment::stored("final", final_image));
  ctx.begin_render_pass("lighting", w, h, 1, loaded, 1);
  record_on_tile_lighting(ctx, setup, options.tonemap, lighting_inputs, final_index);
  ctx.end_render_pass();
  return setup.kit.submit(options.tonemap ? final_image : light);
}

}  // namespace

FrameOutputs DeferredPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  const DeferredOptions options = read_options(in, name(), [&](const PipelineOptions& o) {
    return parse_deferred_options(o, subpasses_ ? DeferredVariant::Subpass : DeferredVariant::Classic);
  });
  const FrameSetup setup(in, options, ctx);
  if (!subpasses_) return render_classic(in, options, setup);
  if (options.two_render_passes) return render_two_render_passes(ctx, in, options, setup);
  const GBufferLayout& layout = options.layout;
  const int w = in.width_px, h = in.height_px;
  const std::vector<PixelFormat> formats = layout.target_formats();
  const std::vector<std::string> names = layout.target_names();
  const int targets = layout.target_count();
  Surface* final_image = options.tonemap ? setup.kit.create_target("final", PixelFormat::RGBA8_SRGB) : nullptr;

  // One render pass; G-buffer and depth live only in tile memory. transient=off backs them by
  // memory as Vulkan-Samples' "transient attachments off" does (store op still DONT_CARE, so
  // nothing more is written); gbuffer_store=store also writes them back, the cost the sample's
  // tutorial warns of.
  Surface* light = options.tonemap ? nullptr : setup.kit.create_target("light", layout.light_format);
  auto on_tile = [&](const std::string& name, PixelFormat format) {
    const Attachment a = Attachment::transient(name, format)
                             .backed_by(options.transient ? nullptr : setup.kit.create_target(name, format))
                             .clear(glm::vec4(0.0f));
    return options.store_gbuffer ? a.store() : a;
  };
  std::vector<AttachmentDesc> a;
  a.push_back(options.tonemap ? Attachment::transient("light", layout.light_format).clear(lit::kBackgroundColor)
                              : Attachment::stored("light", light).clear(lit::kBackgroundColor));
  a.push_back(on_tile("depth", layout.depth_format).clear_depth(1.0f));
  std::vector<int> gbuffer_outputs, lighting_inputs{1};
  if (layout.light_in_gbuffer) gbuffer_outputs.push_back(0);
  for (int k = 0; k < targets; ++k) {
    gbuffer_outputs.push_back(static_cast<int>(a.size()));
    lighting_inputs.push_back(static_cast<int>(a.size()));
    a.push_back(on_tile(names[k], formats[k]));
  }
  const int final_index = static_cast<int>(a.size());
  if (options.tonemap) a.push_back(Attachment::stored("final", final_image));
  ctx.begin_render_pass("deferred", w, h, 1, a, 1);
  ctx.begin_subpass(gbuffer_outputs);
  draw_opaque(ctx, setup, deferred::kGBuffer);
  ctx.end_subpass();
  record_on_tile_lighting(ctx, setup, options.tonemap, lighting_inputs, final_index);
  ctx.end_render_pass();
  return setup.kit.submit(options.tonemap ? final_image : light);
}

FrameOutputs ForwardPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  const DeferredOptions options = read_options(
      in, name(), [](const PipelineOptions& o) { return parse_deferred_options(o, DeferredVariant::Forward); });
  const FrameSetup setup(in, options, ctx);
  const int w = in.width_px, h = in.height_px, samples = options.msaa_samples;
  Surface* final_image = setup.kit.create_target("final", PixelFormat::RGBA8_SRGB);
  // The attachment holding the displayable colour: single-sampled, resolved on tile, or stored
  // multisampled for a separate resolve pass; cleared, or undefined where tonemapping writes it whole.
  Surface* stored_msaa =
      options.separate_resolve ? setup.kit.create_target("color msaa", PixelFormat::RGBA8_SRGB, samples) : nullptr;
  auto display_attachment = [&]() {
    if (samples == 1) return Attachment::stored("color", final_image);
    if (stored_msaa) return Attachment::stored("color msaa", stored_msaa);
    return Attachment::transient("color msaa", PixelFormat::RGBA8_SRGB).resolve_into(final_image);
  };
  std::vector<AttachmentDesc> a;
  if (options.tonemap) {
    a.push_back(Attachment::transient("light", options.layout.light_format).clear(lit::kBackgroundColor));
  } else {
    a.push_back(display_attachment().clear(lit::kBackgroundColor));
  }
  a.push_back(Attachment::transient("depth", PixelFormat::D32_FLOAT).clear_depth(1.0f));
  if (options.tonemap) a.push_back(display_attachment());
  ctx.begin_render_pass("forward", w, h, samples, a, 1);
  ctx.begin_subpass({0});
  draw_opaque(ctx, setup, deferred::kForwardLit);
  draw_transparent(ctx, setup);
  ctx.end_subpass();
  if (options.tonemap) {
    ctx.begin_subpass({2}, {0}, true);
    ctx.draw_full_screen(&setup.library.tonemap_material(false), deferred::kTonemapPass);
    ctx.end_subpass();
  }
  ctx.end_render_pass();
  if (stored_msaa) {
    // vkCmdResolveImage on a tiler: a fragment pass that reads every sample back and writes the
    // averaged pixel.
    ctx.begin_render_pass("msaa resolve", w, h, samples,
                          {Attachment::stored("color msaa", stored_msaa).load().resolve_into(final_image)}, -1);
    ctx.begin_subpass({0});
    ctx.end_subpass();
    ctx.end_render_pass();
  }
  return setup.kit.submit(final_image);
}

namespace {
const PipelineRegistration kDeferredClassic("deferred-classic", [] { return std::make_unique<DeferredPipeline>(false); });
const PipelineRegistration kDeferredSubpass("deferred-subpass", [] { return std::make_unique<DeferredPipeline>(true); });
const PipelineRegistration kForward("forward", [] { return std::make_unique<ForwardPipeline>(); });
}  // namespace

}  // namespace ontile
