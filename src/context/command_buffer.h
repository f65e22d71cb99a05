// Recorded rendering commands (Unity's CommandBuffer, plus the context's own recording): every
// operation is stored in order and executed only by RenderContext::submit().
#pragma once
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "context/culling.h"
#include "context/drawing_settings.h"
#include "context/render_target.h"

namespace ontile {

namespace op {
struct BeginRenderPass {
  std::string name;
  int width_px, height_px, samples;
  std::vector<AttachmentDesc> attachments;
  int depth_index;
};
struct BeginSubpass {
  std::vector<int> color_outputs, inputs;
  bool depth_read_only;
};
struct EndSubpass {};
struct EndRenderPass {};
struct RawDraw { DrawCall draw; };  // pre-built functors (tests, custom passes)
struct SetRenderTarget {
  std::string name;
  std::vector<TargetBinding> colors;
  std::optional<TargetBinding> depth;
};
struct ClearRenderTarget {
  bool clear_color, clear_depth;
  glm::vec4 color;
  float depth;
};
struct DrawRenderers {
  CullingResults culling;
  DrawingSettings drawing;
  FilteringSettings filtering;
};
struct DrawMesh {
  const MeshPrimitive* mesh;
  glm::dmat4 world;
  const RenderMaterial* material;
  std::string pass_name;
  uint32_t primitive_id_base;
};
struct DrawSkybox { CameraMatrices camera; };
struct DrawFullScreen {
  const RenderMaterial* material;
  std::string pass_name;
  RenderTargetRef main_texture{};  // when valid: bound as "_MainTex" the way Blit binds its source
};
struct Blit {
  RenderTargetRef source, destination;
  const RenderMaterial* material;
  std::string pass_name;
};
struct SetGlobalTexture { std::string name; TextureBinding binding; };
struct SetGlobalFloat { std::string name; float value; };
struct SetGlobalVector { std::string name; glm::vec4 value; };
struct SetGlobalMatrix { std::string name; glm::mat4 value; };
struct SetViewProjection { glm::dmat4 view, projection; };
struct GetTemporaryRT { int id; RenderTargetDesc desc; };
struct ReleaseTemporaryRT { int id; };
}  // namespace op

using Command = std::variant<op::BeginRenderPass, op::BeginSubpass, op::EndSubpass,
                             op::EndRenderPass, op::RawDraw, op::SetRenderTarget,
                             op::ClearRenderTarget, op::DrawRenderers, op::DrawMesh,
                             op::DrawSkybox, op::DrawFullScreen, op::Blit, op::SetGlobalTexture, op::SetGlobalFloat,
                             op::SetGlobalVector, op::SetGlobalMatrix, op::SetViewProjection,
                             op::GetTemporaryRT, op::ReleaseTemporaryRT>;

class CommandBuffer {
 public:
  explicit CommandBuffer(std::string name = {}) : name_(std::move(name)) {}
  const std::string& name() const { return name_; }

  // One colour target (or several: MRT) plus an optional depth target; starts a new render
  // pass that lasts until the next set_render_target, blit or the end of the commands.
  void set_render_target(std::vector<TargetBinding> colors, std::optional<TargetBinding> depth = {},
                         std::string pass_name = {});
  // Before any draw of the pass this turns the load actions into Clear (free on a TBDR);
  // after draws it draws a full-screen clear.
  void clear_render_target(bool clear_depth, bool clear_color, glm::vec4 color, float depth = 1.0f);
  // Temporary targets are pooled by descriptor: a release makes the surface reusable.
  void get_temporary_rt(int id, const RenderTargetDesc& desc);
  void release_temporary_rt(int id);
  // Draws a full-screen triangle into `destination` with the material's pass, the source bound
  // as the texture "_MainTex". Ends the current render pass.
  void blit(RenderTargetRef source, RenderTargetRef destination, const RenderMaterial* material,
            const std::string& pass_name);
  void set_global_texture(const std::string& name, TextureBinding binding);
  void set_global_float(const std::string& name, float value);
  void set_global_vector(const std::string& name, glm::vec4 value);
  void set_global_matrix(const std::string& name, glm::mat4 value);
  void set_view_projection(const glm::dmat4& view, const glm::dmat4& projection);
  void draw_mesh(const MeshPrimitive& mesh, const glm::dmat4& world, const RenderMaterial* material,
                 const std::string& pass_name, uint32_t primitive_id_base = 0);

  // A full-screen triangle drawn with the material's pass into the current subpass (Unity's
  // DrawProcedural of 3 vertices, as deferred lighting uses); textures bound to render targets
  // are resolved when the commands execute, so it may read what earlier passes stored.
  void draw_full_screen(const RenderMaterial* material, const std::string& pass_name);

  const std::vector<Command>& commands() const { return commands_; }
  void clear() { commands_.clear(); }

 protected:
  std::vector<Command> commands_;

 private:
  std::string name_;
};

}  // namespace ontile
