// The interface every render pipeline implements, and the registry the CLI lists and picks
// pipelines from. Pipelines talk only to the RenderContext, and register themselves.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "context/render_context.h"
#include "scene/scene.h"

namespace ontile {

// Pipeline-specific options (`ontile render --set key=value`). A pipeline reads its keys with
// take() and rejects the rest with reject_unknown(), so typos are errors, not silent defaults.
class PipelineOptions {
 public:
  void set(const std::string& key, const std::string& value) { values_[key] = value; }
  std::string take(const std::string& key, const std::string& fallback) const;
  void reject_unknown(const std::string& pipeline) const;
  const std::map<std::string, std::string>& values() const { return values_; }  // as given, by key

 private:
  std::map<std::string, std::string> values_;
  mutable std::set<std::string> taken_;
};

struct FrameInputs {
  const Scene* scene = nullptr;
  Camera camera;
  int width_px = 1280, height_px = 720;
  PipelineOptions options;
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

using PipelineFactory = std::function<std::unique_ptr<Pipeline>()>;

// Registers a pipeline under `name` when the program starts: each pipeline's .cpp file defines
// one `const PipelineRegistration` per name (in an unnamed namespace), so adding a pipeline
// edits no list. Two registrations of one name abort at start-up.
struct PipelineRegistration {
  PipelineRegistration(const std::string& name, PipelineFactory factory);
};

// Registered names, sorted.
std::vector<std::string> pipeline_names();
// Throws ontile::Error naming the valid pipelines when `name` is unknown.
std::unique_ptr<Pipeline> make_pipeline(const std::string& name);

}  // namespace ontile
