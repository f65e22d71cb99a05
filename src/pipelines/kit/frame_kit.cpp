// The frame's shared start and end (see frame_kit.h).
#include "pipelines/kit/frame_kit.h"

#include "util/error.h"

namespace ontile {

FrameKit::FrameKit(RenderContext& context, const FrameInputs& inputs, bool reversed_z)
    : context_(context), inputs_(inputs) {
  if (!inputs.scene) throw Error("pipeline: no scene to render");
  matrices_ = camera_matrices(inputs.camera, double(inputs.width_px) / inputs.height_px, reversed_z);
}

const CullingResults& FrameKit::cull(const MaterialFactory& make_material) {
  renderers_ = make_scene_renderers(scene(), make_material);
  culling_ = context_.cull(renderers_.renderers, matrices_);
  return culling_;
}

Surface* FrameKit::create_target(const std::string& name, PixelFormat format, int samples) const {
  return context_.create_surface(name, format, width_px(), height_px(), samples);
}

FrameOutputs FrameKit::submit(Surface* shown) const {
  FrameOutputs out;
  out.report = context_.submit();
  out.color = shown;
  return out;
}

FrameOutputs FrameKit::submit(RenderGraph& graph, GraphResource shown) const {
  graph.mark_output(shown);
  graph.execute(context_);
  return submit(graph.surface(shown));
}

}  // namespace ontile
