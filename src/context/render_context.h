// The render context pipelines talk to (Unity's ScriptableRenderContext): it owns render
// targets, culls renderers, records render passes, draws and command buffers, and executes
// nothing until submit(), which runs everything in recorded order on the tiler and returns
// the frame's traffic report.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "context/command_buffer.h"
#include "context/frame_report.h"
#include "context/pass_observer.h"
#include "context/render_graph_compiler.h"
#include "tiler/render_pass_executor.h"

namespace ontile {

struct ContextConfig {
  int threads = 0;  // 0: all hardware threads
  TilerConfig tiler;
  RenderGraphMode render_graph = RenderGraphMode::Off;  // how RenderGraph::execute compiles
  // Told about every render pass after it ran (not owned; it must outlive submit()). Null, the
  // default, costs nothing: no surface is read or copied.
  PassObserver* pass_observer = nullptr;
};

// Temporary render targets, pooled by descriptor across frames of one context.
struct RenderTargetPool {
  struct Entry {
    RenderTargetDesc desc;
    std::unique_ptr<Surface> surface;
    bool in_use = false;
  };
  std::vector<Entry> entries;
  Surface* acquire(const RenderTargetDesc& desc, const std::string& name);
  void release(Surface* surface);
};

class RenderContext : private CommandBuffer {
 public:
  explicit RenderContext(ContextConfig config = {});

  // A persistent render target in external memory, owned by the context.
  Surface* create_surface(const std::string& name, PixelFormat format, int width_px,
                          int height_px, int samples = 1);

  // Explicit render passes (Vulkan-style); attachments with no surface are transient.
  void begin_render_pass(const std::string& name, int width_px, int height_px, int samples,
                         std::vector<AttachmentDesc> attachments, int depth_index);
  void begin_subpass(std::vector<int> color_outputs, std::vector<int> inputs = {},
                     bool depth_read_only = false);
  // A draw with pre-built functors; they must outlive submit().
  void draw(const DrawCall& draw);
  void end_subpass();
  void end_render_pass();

  CullingResults cull(const std::vector<Renderer>& renderers, const CameraMatrices& camera,
                      const CullingParameters& params = {}) const;
  void draw_renderers(const CullingResults& culling, const DrawingSettings& drawing,
                      const FilteringSettings& filtering);
  void draw_skybox(const CameraMatrices& camera);
  void execute_command_buffer(const CommandBuffer& buffer);
  // The recording API of command buffers is available on the context too.
  using CommandBuffer::blit;
  using CommandBuffer::clear_render_target;
  using CommandBuffer::draw_full_screen;
  using CommandBuffer::draw_mesh;
  using CommandBuffer::get_temporary_rt;
  using CommandBuffer::release_temporary_rt;
  using CommandBuffer::set_global_float;
  using CommandBuffer::set_global_matrix;
  using CommandBuffer::set_global_texture;
  using CommandBuffer::set_global_vector;
  using CommandBuffer::set_render_target;
  using CommandBuffer::set_view_projection;

  // What a render graph's compiler decided, reported by the next submit() (JSON "graph").
  void add_graph_report(GraphReport report) { graph_report_ = std::move(report); }

  // Executes everything recorded since the last submit, in recorded order.
  FrameReport submit();
  const ContextConfig& config() const { return config_; }

 private:
  ContextConfig config_;
  std::vector<std::unique_ptr<Surface>> surfaces_;
  RenderTargetPool pool_;
  bool in_pass_ = false, in_subpass_ = false;
  std::optional<GraphReport> graph_report_;
};

}  // namespace ontile
