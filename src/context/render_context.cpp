// Render context recording and submission (see render_context.h; execution in
// frame_executor.cpp).
#include "context/render_context.h"

#include "context/detail/frame_executor.h"
#include "util/error.h"

namespace ontile {

Surface* RenderTargetPool::acquire(const RenderTargetDesc& desc, const std::string& name) {
  for (Entry& e : entries) {
    if (!e.in_use && e.desc == desc) {
      e.in_use = true;
      return e.surface.get();
    }
  }
  entries.push_back({desc, std::make_unique<Surface>(name, desc.format, desc.width_px,
                                                     desc.height_px, desc.samples), true});
  return entries.back().surface.get();
}

void RenderTargetPool::release(Surface* surface) {
  for (Entry& e : entries) {
    if (e.surface.get() == surface) e.in_use = false;
  }
}

RenderContext::RenderContext(ContextConfig config) : config_(config) {
  if (config_.threads < 0) throw Error("thread count must be >= 0");
}

Surface* RenderContext::create_surface(const std::string& name, PixelFormat format, int width_px,
                                       int height_px, int samples) {
  surfaces_.push_back(std::make_unique<Surface>(name, format, width_px, height_px, samples));
  return surfaces_.back().get();
}

void RenderContext::begin_render_pass(const std::string& name, int width_px, int height_px,
                                      int samples, std::vector<AttachmentDesc> attachments,
                                      int depth_index) {
  if (in_pass_) throw Error("begin_render_pass('" + name + "') inside another render pass");
  commands_.push_back(op::BeginRenderPass{name, width_px, height_px, samples, std::move(attachments),
                                          depth_index});
  in_pass_ = true;
}

void RenderContext::begin_subpass(std::vector<int> color_outputs, std::vector<int> inputs,
                                  bool depth_read_only) {
  if (!in_pass_ || in_subpass_) throw Error("begin_subpass outside a render pass or inside a subpass");
  commands_.push_back(op::BeginSubpass{std::move(color_outputs), std::move(inputs), depth_read_only});
  in_subpass_ = true;
}

void RenderContext::draw(const DrawCall& draw) {
  if (!in_subpass_) throw Error("draw recorded outside a subpass");
  commands_.push_back(op::RawDraw{draw});
}

void RenderContext::end_subpass() {
  if (!in_subpass_) throw Error("end_subpass without begin_subpass");
  commands_.push_back(op::EndSubpass{});
  in_subpass_ = false;
}

void RenderContext::end_render_pass() {
  if (!in_pass_ || in_subpass_) throw Error("end_render_pass without a matching begin or with an open subpass");
  commands_.push_back(op::EndRenderPass{});
  in_pass_ = false;
}

CullingResults RenderContext::cull(const std::vector<Renderer>& renderers,
                                   const CameraMatrices& camera,
                                   const CullingParameters& params) const {
  return cull_renderers(renderers, camera, params);
}

void RenderContext::draw_renderers(const CullingResults& culling, const DrawingSettings& drawing,
                                   const FilteringSettings& filtering) {
  commands_.push_back(op::DrawRenderers{culling, drawing, filtering});
}

void RenderContext::draw_skybox(const CameraMatrices& camera) {
  commands_.push_back(op::DrawSkybox{camera});
}

void RenderContext::execute_command_buffer(const CommandBuffer& buffer) {
  commands_.insert(commands_.end(), buffer.commands().begin(), buffer.commands().end());
}

FrameReport RenderContext::submit() {
  if (in_pass_) throw Error("submit() inside an open render pass");
  std::vector<Command> commands;
  commands.swap(commands_);
  FrameExecutor executor(config_, pool_);
  FrameReport report = executor.run(commands);
  report.graph = std::move(graph_report_);
  graph_report_.reset();
  return report;
}

}  // namespace ontile
