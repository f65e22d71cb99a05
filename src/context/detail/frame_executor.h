// Executes a frame's recorded commands in order: builds render passes (explicit ones, and the
// implicit ones set_render_target and blit open), expands draw_renderers into sorted draws,
// runs each pass on the tiler as soon as it closes, and collects the traffic report.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <tbb/task_arena.h>

#include "context/render_context.h"

namespace ontile {

class FrameExecutor {
 public:
  FrameExecutor(const ContextConfig& config, RenderTargetPool& pool);
  FrameReport run(const std::vector<Command>& commands);

  void operator()(const op::BeginRenderPass& c);
  void operator()(const op::BeginSubpass& c);
  void operator()(const op::EndSubpass& c);
  void operator()(const op::EndRenderPass& c);
  void operator()(const op::RawDraw& c);
  void operator()(const op::SetRenderTarget& c);
  void operator()(const op::ClearRenderTarget& c);
  void operator()(const op::DrawRenderers& c);
  void operator()(const op::DrawMesh& c);
  void operator()(const op::DrawSkybox& c);
  void operator()(const op::DrawFullScreen& c);
  void operator()(const op::Blit& c);
  void operator()(const op::SetGlobalTexture& c) { globals_.textures[c.name] = c.binding; }
  void operator()(const op::SetGlobalFloat& c) { globals_.floats[c.name] = c.value; }
  void operator()(const op::SetGlobalVector& c) { globals_.vectors[c.name] = c.value; }
  void operator()(const op::SetGlobalMatrix& c) { globals_.matrices[c.name] = c.value; }
  void operator()(const op::SetViewProjection& c);
  void operator()(const op::GetTemporaryRT& c);
  void operator()(const op::ReleaseTemporaryRT& c);

 private:
  struct OpenPass {
    RenderPassDesc desc;
    bool implicit = false;
    bool in_subpass = false;
    bool has_draws = false;
  };

  Surface* resolve(const RenderTargetRef& ref, const char* what);
  // The texture a binding samples: its texture, or a render target's contents (one texture per
  // surface and pass). texel_reads: the shader only fetches texels, so packed formats come as
  // surface views too (DrawContext::texel_source).
  std::shared_ptr<const Texture2D> texture_of(const TextureBinding& binding, bool texel_reads = false);
  SubpassDesc& current_subpass(const char* what);
  void close_pass();
  void add_draw(DrawCall draw);
  void draw_with_pass(const MeshPrimitive* mesh, const glm::dmat4& world,
                      const RenderMaterial& material, const ShaderPass& pass,
                      uint32_t primitive_id_base, const PropertyBlock* extra = nullptr);
  void add_full_screen_draw(std::unique_ptr<VertexShader> vs, std::unique_ptr<FragmentShader> fs,
                            const PassState& state);

  const ContextConfig& config_;
  RenderTargetPool& pool_;
  tbb::task_arena arena_;
  std::unique_ptr<MemoryModel> memory_;  // the frame's external memory (one texture cache state)
  FrameReport frame_;
  PropertyBlock globals_;
  CameraMatrices camera_;
  std::map<int, Surface*> temporaries_;
  std::optional<OpenPass> pass_;
  int implicit_pass_count_ = 0;
  // Functors and textures the open pass's draws point to, kept alive until it executes.
  std::vector<std::unique_ptr<VertexShader>> vertex_shaders_;
  std::vector<std::unique_ptr<FragmentShader>> fragment_shaders_;
  std::vector<std::shared_ptr<const Texture2D>> textures_;
  // The open pass's textures of render targets: views, or decoded copies of packed formats.
  std::map<const Surface*, std::shared_ptr<const Texture2D>> surface_textures_;
};

}  // namespace ontile
