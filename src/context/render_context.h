// The render context pipelines talk to: it owns render-target surfaces, records render passes,
// subpasses and draws, and executes nothing until submit(), which runs the recorded passes in
// order on the tiler and returns the frame's traffic report.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "context/frame_report.h"
#include "tiler/render_pass.h"
#include "tiler/render_pass_executor.h"

namespace ontile {

struct ContextConfig {
  int threads = 0;  // 0: all hardware threads
  TilerConfig tiler;
};

class RenderContext {
 public:
  explicit RenderContext(ContextConfig config = {});

  // A render target in external memory, owned by the context for its lifetime.
  Surface* create_surface(const std::string& name, PixelFormat format, int width_px,
                          int height_px, int samples = 1);

  void begin_render_pass(const std::string& name, int width_px, int height_px, int samples,
                         std::vector<AttachmentDesc> attachments, int depth_index);
  void begin_subpass(std::vector<int> color_outputs, std::vector<int> inputs = {},
                     bool depth_read_only = false);
  // Shaders referenced by the draw must outlive submit().
  void draw(const DrawCall& draw);
  void end_subpass();
  void end_render_pass();

  // Executes everything recorded since the last submit, in recorded order.
  FrameReport submit();
  const ContextConfig& config() const { return config_; }

 private:
  ContextConfig config_;
  std::vector<std::unique_ptr<Surface>> surfaces_;
  std::vector<RenderPassDesc> recorded_;
  bool in_pass_ = false, in_subpass_ = false;
};

}  // namespace ontile
