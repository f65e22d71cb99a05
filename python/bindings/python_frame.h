// The frame a Python pipeline records into (ontile.Frame): the FrameKit of a C++ pipeline plus
// what Python cannot keep alive by itself until submit: shader libraries, the renderers and
// culling results made with their materials, and render graphs. A Python pipeline holds only
// references into it; once its render() returns the frame is closed and refuses every call.
#pragma once
#include <deque>
#include <memory>
#include <optional>

#include <pybind11/pybind11.h>

#include "pipelines/kit/pipeline_api.h"
#include "shader_libraries.h"

namespace ontile::python {

class PythonFrame {
 public:
  PythonFrame(RenderContext& context, const FrameInputs& inputs, std::string pipeline)
      : context_(&context), inputs_(&inputs), pipeline_(std::move(pipeline)), kit_(context, inputs) {}

  RenderContext& context() const;
  const FrameInputs& inputs() const;
  const FrameKit& kit() const;
  const std::string& pipeline() const { return pipeline_; }

  ShaderLibrary& add_library(std::unique_ptr<ShaderLibrary> library);
  // FrameKit::cull with the library's materials; kept until the frame closes, so one frame may
  // cull with several libraries.
  const CullingResults& cull(const ShaderLibrary& library);
  RenderGraph& add_graph();

  void set_outputs(FrameOutputs outputs);
  // What submit returned; throws ontile::Error when the pipeline never submitted.
  FrameOutputs take_outputs();
  void close() { open_ = false; }

 private:
  void check_open() const;
  RenderContext* context_;
  const FrameInputs* inputs_;
  std::string pipeline_;
  FrameKit kit_;
  bool open_ = true;
  std::deque<std::unique_ptr<ShaderLibrary>> libraries_;
  std::deque<SceneRenderers> renderers_;
  std::deque<CullingResults> cullings_;
  std::deque<RenderGraph> graphs_;
  std::optional<FrameOutputs> outputs_;
};

// A pipeline object written in Python (an ontile.Pipeline: `name` and `render(frame)`).
std::unique_ptr<Pipeline> make_python_pipeline(pybind11::object pipeline);

}  // namespace ontile::python
