// Render context recording and submission (see render_context.h).
#include "context/render_context.h"

#include <chrono>
#include <thread>

#include <tbb/task_arena.h>

#include "util/error.h"

namespace ontile {

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
  RenderPassDesc pass;
  pass.name = name;
  pass.width_px = width_px;
  pass.height_px = height_px;
  pass.samples = samples;
  pass.attachments = std::move(attachments);
  pass.depth_index = depth_index;
  recorded_.push_back(std::move(pass));
  in_pass_ = true;
}

void RenderContext::begin_subpass(std::vector<int> color_outputs, std::vector<int> inputs,
                                  bool depth_read_only) {
  if (!in_pass_ || in_subpass_) throw Error("begin_subpass outside a render pass or inside a subpass");
  SubpassDesc sub;
  sub.color_outputs = std::move(color_outputs);
  sub.inputs = std::move(inputs);
  sub.depth_read_only = depth_read_only;
  recorded_.back().subpasses.push_back(std::move(sub));
  in_subpass_ = true;
}

void RenderContext::draw(const DrawCall& draw) {
  if (!in_subpass_) throw Error("draw recorded outside a subpass");
  recorded_.back().subpasses.back().draws.push_back(draw);
}

void RenderContext::end_subpass() {
  if (!in_subpass_) throw Error("end_subpass without begin_subpass");
  in_subpass_ = false;
}

void RenderContext::end_render_pass() {
  if (!in_pass_ || in_subpass_) throw Error("end_render_pass without a matching begin or with an open subpass");
  in_pass_ = false;
}

FrameReport RenderContext::submit() {
  if (in_pass_) throw Error("submit() inside an open render pass");
  FrameReport frame;
  const int threads = config_.threads > 0 ? config_.threads
                                          : static_cast<int>(std::thread::hardware_concurrency());
  frame.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  tbb::task_arena arena(threads);
  arena.execute([&] {
    for (const RenderPassDesc& pass : recorded_) {
      frame.passes.push_back(execute_render_pass(pass, config_.tiler));
    }
  });
  frame.total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  recorded_.clear();
  return frame;
}

}  // namespace ontile
