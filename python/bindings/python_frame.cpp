// PythonFrame and the Pipeline adapter that runs a Python pipeline (see python_frame.h).
#include "python_frame.h"

#include "util/error.h"

namespace py = pybind11;

namespace ontile::python {

void PythonFrame::check_open() const {
  if (!open_) throw Error("pipeline '" + pipeline_ + "': the frame is closed (its render() returned)");
}

RenderContext& PythonFrame::context() const {
  check_open();
  return *context_;
}

const FrameInputs& PythonFrame::inputs() const {
  check_open();
  return *inputs_;
}

const FrameKit& PythonFrame::kit() const {
  check_open();
  return kit_;
}

ShaderLibrary& PythonFrame::add_library(std::unique_ptr<ShaderLibrary> library) {
  check_open();
  libraries_.push_back(std::move(library));
  return *libraries_.back();
}

const CullingResults& PythonFrame::cull(const ShaderLibrary& library) {
  check_open();
  // FrameKit::cull's two steps, with renderers and results kept per call (deque: stable).
  renderers_.push_back(make_scene_renderers(kit_.scene(), [&](const Material& m) { return library.make_material(m); }));
  cullings_.push_back(context_->cull(renderers_.back().renderers, kit_.matrices()));
  return cullings_.back();
}

RenderGraph& PythonFrame::add_graph() {
  check_open();
  return graphs_.emplace_back();
}

void PythonFrame::set_outputs(FrameOutputs outputs) {
  check_open();
  if (outputs_) throw Error("pipeline '" + pipeline_ + "': the frame was already submitted");
  outputs_ = std::move(outputs);
}

FrameOutputs PythonFrame::take_outputs() {
  if (!outputs_) throw Error("pipeline '" + pipeline_ + "': render() returned without frame.submit()");
  FrameOutputs out = std::move(*outputs_);
  outputs_.reset();
  return out;
}

namespace {

class PythonPipeline final : public Pipeline {
 public:
  explicit PythonPipeline(py::object pipeline) : pipeline_(std::move(pipeline)) {
    name_ = py::str(pipeline_.attr("name")).cast<std::string>();
    if (name_.empty()) throw Error("a Python pipeline needs a non-empty `name`");
  }
  std::string name() const override { return name_; }
  std::string description() const override {
    return py::hasattr(pipeline_, "description") ? py::str(pipeline_.attr("description")).cast<std::string>() : "";
  }
  FrameOutputs render(RenderContext& context, const FrameInputs& inputs) override {
    auto frame = std::make_shared<PythonFrame>(context, inputs, name_);
    const py::object handle = py::cast(frame);
    try {
      pipeline_.attr("render")(handle);
    } catch (...) {
      frame->close();
      throw;
    }
    frame->close();
    return frame->take_outputs();
  }

 private:
  py::object pipeline_;
  std::string name_;
};

}  // namespace

std::unique_ptr<Pipeline> make_python_pipeline(py::object pipeline) {
  return std::make_unique<PythonPipeline>(std::move(pipeline));
}

}  // namespace ontile::python
