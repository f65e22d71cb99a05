// The start and end that every pipeline's frame shares: options read strictly, the camera's
// matrices at the frame's aspect, the scene's renderers with the pipeline's materials, culling,
// frame-sized targets, and the submit that returns the image and its report.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include "context/camera_matrices.h"
#include "context/render_graph.h"
#include "context/scene_renderers.h"
#include "pipelines/kit/pipeline.h"

namespace ontile {

// Parses a pipeline's options with `parse` and rejects every key it did not read, so that a
// typo in `--set` is an error rather than a silent default.
template <class Parse>
auto read_options(const FrameInputs& in, const std::string& pipeline, Parse&& parse) {
  auto options = parse(in.options);
  in.options.reject_unknown(pipeline);
  return options;
}

class FrameKit {
 public:
  using MaterialFactory = std::function<std::unique_ptr<RenderMaterial>(const Material&)>;

  // reversed_z: depth 1 at the near plane (camera_matrices.h). Throws when there is no scene.
  FrameKit(RenderContext& context, const FrameInputs& inputs, bool reversed_z = false);

  RenderContext& context() const { return context_; }
  const Scene& scene() const { return *inputs_.scene; }
  const Camera& camera() const { return inputs_.camera; }
  const CameraMatrices& matrices() const { return matrices_; }
  int width_px() const { return inputs_.width_px; }
  int height_px() const { return inputs_.height_px; }

  // One renderer per mesh primitive, each with the material `make_material` makes from its
  // glTF material, culled against the camera. Kept alive by the kit until submit.
  const CullingResults& cull(const MaterialFactory& make_material);
  const CullingResults& culling() const { return culling_; }
  const SceneRenderers& renderers() const { return renderers_; }

  // A frame-sized surface owned by the context.
  Surface* create_target(const std::string& name, PixelFormat format, int samples = 1) const;

  // Runs everything recorded and returns `shown` with the frame's report.
  FrameOutputs submit(Surface* shown) const;
  // Marks `shown` as the graph's output, executes the graph into the context, then submits.
  FrameOutputs submit(RenderGraph& graph, GraphResource shown) const;

 private:
  RenderContext& context_;
  const FrameInputs& inputs_;
  CameraMatrices matrices_;
  SceneRenderers renderers_;
  CullingResults culling_;
};

}  // namespace ontile
