// The interface every render pipeline implements, and the registry the CLI lists and picks
// pipelines from. Pipelines talk only to the RenderContext.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "context/render_context.h"
#include "scene/scene.h"

namespace ontile {

struct FrameInputs {
  const Scene* scene = nullptr;
  Camera camera;
  int width_px = 1280, height_px = 720;
};

struct FrameOutputs {
  Surface* color = nullptr;  // final image, owned by the context
  FrameReport report;
};

class Pipeline {
 public:
  virtual ~Pipeline() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  // Records the frame into the context, submits it and returns the final colour surface.
  virtual FrameOutputs render(RenderContext& context, const FrameInputs& inputs) = 0;
};

std::vector<std::string> pipeline_names();
// Throws ontile::Error naming the valid pipelines when `name` is unknown.
std::unique_ptr<Pipeline> make_pipeline(const std::string& name);

}  // namespace ontile
