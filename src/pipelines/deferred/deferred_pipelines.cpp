// The deferred pipelines and the forward baseline (see deferred_pipelines.h).
#include "pipelines/deferred/deferred_pipelines.h"

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

TextureBinding texture_of(Surface* surface) { return {nullptr, RenderTargetRef::of(surface), {}}; }

}  // namespace

FrameOutputs DeferredPipeline::render(RenderContext& ctx, const FrameInputs& in) {
  const DeferredOptions options =
      parse_deferred_options(in.options, subpasses_ ? DeferredVariant::Subpass : DeferredVariant::Classic);
  in.options.reject_unknown(name());
  const FrameSetup setup(in, options, ctx);
  const GBufferLayout& layout = options.layout;
  const int w = in.width_px, h = in.height_px;
  const std::vector<PixelFormat> formats = layout.target_formats();
  const std::vector<std::string> names = layout.target_names();
  const int targets = layout.target_count();
  Surface* final_image = options.tonemap ? ctx.create_surface("final", PixelFormat::RGBA8_SRGB, w, h) : nullptr;
  FrameOutputs out;

  if (!subpasses_) {
    // Pass 1 stores the G-buffer and depth; pass 2 reads them back as textures.
    Surface* light = ctx.create_surface("light", layout.light_format, w, h);
    Surface* depth = ctx.create_surface("depth", layout.depth_format, w, h);
    std::vector<Surface*> gbuffer;
    for (int k = 0; k < targets; ++k) gbuffer.push_back(ctx.create_surface(names[k], formats[k], w, h));
    std::vector<AttachmentDesc> a;
    std::vector<int> outputs;
    if (layout.light_in_gbuffer) {
      a.push_back(attachment("light", layout.light_format, light, LoadAction::Clear, StoreAction::Store, lit::kBackgroundColor));
      outputs.push_back(0);
    }
    for (int k = 0; k < targets; ++k) {
      outputs.push_back(static_cast<int>(a.size()));
      a.push_back(attachment(names[k], formats[k], gbuffer[k], LoadAction::Clear, StoreAction::Store));
    }
    a.push_back(attachment("depth", layout.depth_format, depth, LoadAction::Clear, StoreAction::Store, glm::vec4(1.0f)));
    ctx.begin_render_pass("gbuffer", w, h, 1, a, static_cast<int>(a.size()) - 1);
    ctx.begin_subpass(outputs);
    draw_opaque(ctx, setup, deferred::kGBuffer);
    ctx.end_subpass();
    ctx.end_render_pass();

    CommandBuffer bind("bind G-buffer textures");
    bind.set_global_texture(deferred::kDepthTexture, texture_of(depth));
    for (int k = 0; k < targets; ++k) bind.set_global_texture(deferred::gbuffer_texture(k), texture_of(gbuffer[k]));
    ctx.execute_command_buffer(bind);
    // Unity's lighting pass loads the accumulation the G-buffer pass started; Vulkan-Samples'
    // clears the light target.
    const LoadAction light_load = layout.light_in_gbuffer ? LoadAction::Load : LoadAction::Clear;
    ctx.begin_render_pass("lighting", w, h, 1,
                          {attachment("light", layout.light_format, light, light_load, StoreAction::Store, lit::kBackgroundColor)}, -1);
    ctx.begin_subpass({0});
    ctx.draw_full_screen(&setup.library.lighting_material(true), deferred::kLightingPass);
    ctx.end_subpass();
    ctx.end_render_pass();

    if (setup.has_transparent) {
      ctx.begin_render_pass("transparent", w, h, 1,
                            {attachment("light", layout.light_format, light, LoadAction::Load, StoreAction::Store),
                             attachment("depth", layout.depth_format, depth, LoadAction::Load, StoreAction::DontCare)},
                            1);
      ctx.begin_subpass({0}, {}, true);
      draw_transparent(ctx, setup);
      ctx.end_subpass();
      ctx.end_render_pass();
    }
    if (options.tonemap) {
      CommandBuffer bind_light("bind light accumulation");
      bind_light.set_global_texture(deferred::kLightTexture, texture_of(light));
      ctx.execute_command_buffer(bind_light);
      ctx.begin_render_pass("tonemap", w, h, 1,
                            {attachment("final", PixelFormat::RGBA8_SRGB, final_image, LoadAction::DontCare, StoreAction::Store)},
                            -1);
      ctx.begin_subpass({0});
      ctx.draw_full_screen(&setup.library.tonemap_material(true), deferred::kTonemapPass);
      ctx.end_subpass();
      ctx.end_render_pass();
    }
    out.report = ctx.submit();
    out.color = options.tonemap ? final_image : light;
    return out;
  }

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
