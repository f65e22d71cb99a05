// The deferred pipelines and the forward baseline (see deferred_pipelines.h).
#include "pipelines/deferred/deferred_pipelines.h"

#include "context/render_graph.h"
#include "context/scene_renderers.h"
#include "pipelines/deferred/deferred_options.h"
#include "pipelines/deferred/deferred_shaders.h"
#include "pipelines/deferred/scene_lighting_setup.h"
#include "pipelines/lit_shader.h"

namespace ontile {
namespace {


// What every variant prepares before recording: lights, shaders, renderers and culling. Built
// in place (the shader library points to the lighting), alive until submit() returns.
struct FrameSetup {
  FrameSetup(const FrameInputs& in, const DeferredOptions& options, RenderContext& ctx)
      : camera(camera_matrices(in.camera, double(in.width_px) / in.height_px)),
        lighting(make_scene_lighting(*in.scene, options.generated_lights, camera, in.width_px, in.height_px)),
        library(options.layout, lighting, camera, in.width_px, in.height_px),
        renderers(make_scene_renderers(*in.scene, [&](const Material& m) { return library.make_material(m); })),
        culling(ctx.cull(renderers.renderers, camera)) {
    for (uint32_t i : culling.visible) {
      if (renderers.renderers[i].material->render_queue > RenderQueueRange::opaque().upper) has_transparent = true;
    }
  }
  CameraMatrices camera;
  SceneLighting lighting;
  DeferredShaderLibrary library;
  SceneRenderers renderers;
  CullingResults culling;
  bool has_transparent = false;
};

AttachmentDesc attachment(const std::string& name, PixelFormat format, Surface* surface, LoadAction load,
                          StoreAction store, glm::vec4 clear = glm::vec4(0.0f)) {
  return {name, format, load, store, clear, surface, nullptr};
}

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
FrameOutputs render_classic(RenderContext& ctx, const FrameInputs& in, const DeferredOptions& options,
                            const FrameSetup& setup) {
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
  const GraphResource shown = options.tonemap ? final_image : light;
  graph.mark_output(shown);
  graph.execute(ctx);
  FrameOutputs out;
  out.report = ctx.submit();
  out.color = graph.surface(shown);
  return out;
}

}  // namespace

FrameOutputs DeferredPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  const DeferredOptions options =
      parse_deferred_options(in.options, subpasses_ ? DeferredVariant::Subpass : DeferredVariant::Classic);
  in.options.reject_unknown(name());
  const FrameSetup setup(in, options, ctx);
  if (!subpasses_) return render_classic(ctx, in, options, setup);
  const GBufferLayout& layout = options.layout;
  const int w = in.width_px, h = in.height_px;
  const std::vector<PixelFormat> formats = layout.target_formats();
  const std::vector<std::string> names = layout.target_names();
  const int targets = layout.target_count();
  Surface* final_image = options.tonemap ? ctx.create_surface("final", PixelFormat::RGBA8_SRGB, w, h) : nullptr;
  FrameOutputs out;

  // One render pass; G-buffer and depth live only in tile memory. transient=off backs them by
  // memory as Vulkan-Samples' "transient attachments off" does (store op still DONT_CARE, so
  // nothing more is written); gbuffer_store=store also writes them back, the cost the sample's
  // tutorial warns of.
  Surface* light = options.tonemap ? nullptr : ctx.create_surface("light", layout.light_format, w, h);
  auto on_tile = [&](const std::string& name, PixelFormat format) -> Surface* {
    return options.transient ? nullptr : ctx.create_surface(name, format, w, h);
  };
  const StoreAction on_tile_store = options.store_gbuffer ? StoreAction::Store : StoreAction::DontCare;
  std::vector<AttachmentDesc> a;
  a.push_back(attachment("light", layout.light_format, light, LoadAction::Clear,
                         options.tonemap ? StoreAction::DontCare : StoreAction::Store, lit::kBackgroundColor));
  a.push_back(attachment("depth", layout.depth_format, on_tile("depth", layout.depth_format), LoadAction::Clear,
                         on_tile_store, glm::vec4(1.0f)));
  std::vector<int> gbuffer_outputs, lighting_inputs{1};
  if (layout.light_in_gbuffer) gbuffer_outputs.push_back(0);
  for (int k = 0; k < targets; ++k) {
    gbuffer_outputs.push_back(static_cast<int>(a.size()));
    lighting_inputs.push_back(static_cast<int>(a.size()));
    a.push_back(attachment(names[k], formats[k], on_tile(names[k], formats[k]), LoadAction::Clear, on_tile_store));
  }
  const int final_index = static_cast<int>(a.size());
  if (options.tonemap) {
    a.push_back(attachment("final", PixelFormat::RGBA8_SRGB, final_image, LoadAction::DontCare, StoreAction::Store));
  }
  ctx.begin_render_pass("deferred", w, h, 1, a, 1);
  ctx.begin_subpass(gbuffer_outputs);
  draw_opaque(ctx, setup, deferred::kGBuffer);
  ctx.end_subpass();
  ctx.begin_subpass({0}, lighting_inputs, true);
  ctx.draw_full_screen(&setup.library.lighting_material(false), deferred::kLightingPass);
  ctx.end_subpass();
  if (setup.has_transparent) {
    ctx.begin_subpass({0}, {}, true);
    draw_transparent(ctx, setup);
    ctx.end_subpass();
  }
  if (options.tonemap) {
    ctx.begin_subpass({final_index}, {0}, true);
    ctx.draw_full_screen(&setup.library.tonemap_material(false), deferred::kTonemapPass);
    ctx.end_subpass();
  }
  ctx.end_render_pass();
  out.report = ctx.submit();
  out.color = options.tonemap ? final_image : light;
  return out;
}

FrameOutputs ForwardPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  const DeferredOptions options = parse_deferred_options(in.options, DeferredVariant::Forward);
  in.options.reject_unknown(name());
  const FrameSetup setup(in, options, ctx);
  const int w = in.width_px, h = in.height_px, samples = options.msaa_samples;
  Surface* final_image = ctx.create_surface("final", PixelFormat::RGBA8_SRGB, w, h);
  // The attachment holding the displayable colour: single-sampled, resolved on tile, or stored
  // multisampled for a separate resolve pass.
  Surface* stored_msaa = options.separate_resolve
                             ? ctx.create_surface("color msaa", PixelFormat::RGBA8_SRGB, w, h, samples)
                             : nullptr;
  auto display_attachment = [&](LoadAction load, glm::vec4 clear) {
    if (samples == 1) return attachment("color", PixelFormat::RGBA8_SRGB, final_image, load, StoreAction::Store, clear);
    if (stored_msaa) return attachment("color msaa", PixelFormat::RGBA8_SRGB, stored_msaa, load, StoreAction::Store, clear);
    AttachmentDesc resolving = attachment("color msaa", PixelFormat::RGBA8_SRGB, nullptr, load, StoreAction::Resolve, clear);
    resolving.resolve_surface = final_image;
    return resolving;
  };
  std::vector<AttachmentDesc> a;
  if (options.tonemap) {
    a.push_back(attachment("light", options.layout.light_format, nullptr, LoadAction::Clear, StoreAction::DontCare, lit::kBackgroundColor));
  } else {
    a.push_back(display_attachment(LoadAction::Clear, lit::kBackgroundColor));
  }
  a.push_back(attachment("depth", PixelFormat::D32_FLOAT, nullptr, LoadAction::Clear, StoreAction::DontCare, glm::vec4(1.0f)));
  if (options.tonemap) a.push_back(display_attachment(LoadAction::DontCare, glm::vec4(0.0f)));
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
    AttachmentDesc resolve = attachment("color msaa", PixelFormat::RGBA8_SRGB, stored_msaa, LoadAction::Load, StoreAction::Resolve);
    resolve.resolve_surface = final_image;
    ctx.begin_render_pass("msaa resolve", w, h, samples, {resolve}, -1);
    ctx.begin_subpass({0});
    ctx.end_subpass();
    ctx.end_render_pass();
  }
  FrameOutputs out;
  out.report = ctx.submit();
  out.color = final_image;
  return out;
}

}  // namespace ontile
