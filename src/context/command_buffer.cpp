// CommandBuffer recording (see command_buffer.h).
#include "context/command_buffer.h"

#include "util/error.h"

namespace ontile {

void CommandBuffer::set_render_target(std::vector<TargetBinding> colors,
                                      std::optional<TargetBinding> depth, std::string pass_name) {
  commands_.push_back(op::SetRenderTarget{std::move(pass_name), std::move(colors), depth});
}

void CommandBuffer::clear_render_target(bool clear_depth, bool clear_color, glm::vec4 color,
                                        float depth) {
  commands_.push_back(op::ClearRenderTarget{clear_color, clear_depth, color, depth});
}

void CommandBuffer::get_temporary_rt(int id, const RenderTargetDesc& desc) {
  commands_.push_back(op::GetTemporaryRT{id, desc});
}

void CommandBuffer::release_temporary_rt(int id) { commands_.push_back(op::ReleaseTemporaryRT{id}); }

void CommandBuffer::blit(RenderTargetRef source, RenderTargetRef destination,
                         const RenderMaterial* material, const std::string& pass_name) {
  commands_.push_back(op::Blit{source, destination, material, pass_name});
}

void CommandBuffer::set_global_texture(const std::string& name, TextureBinding binding) {
  commands_.push_back(op::SetGlobalTexture{name, std::move(binding)});
}

void CommandBuffer::set_global_float(const std::string& name, float value) {
  commands_.push_back(op::SetGlobalFloat{name, value});
}

void CommandBuffer::set_global_vector(const std::string& name, glm::vec4 value) {
  commands_.push_back(op::SetGlobalVector{name, value});
}

void CommandBuffer::set_global_matrix(const std::string& name, glm::mat4 value) {
  commands_.push_back(op::SetGlobalMatrix{name, value});
}

void CommandBuffer::set_view_projection(const glm::dmat4& view, const glm::dmat4& projection) {
  commands_.push_back(op::SetViewProjection{view, projection});
}

void CommandBuffer::draw_mesh(const MeshPrimitive& mesh, const glm::dmat4& world,
                              const RenderMaterial* material, const std::string& pass_name,
                              uint32_t primitive_id_base) {
  commands_.push_back(op::DrawMesh{&mesh, world, material, pass_name, primitive_id_base});
}

void CommandBuffer::draw_full_screen(const RenderMaterial* material, const std::string& pass_name) {
  if (!material) throw Error("draw_full_screen: no material (pass '" + pass_name + "')");
  commands_.push_back(op::DrawFullScreen{material, pass_name});
}

}  // namespace ontile
