// What the pieces of the `ontile._ontile` extension share: the loaded scene and a rendered
// frame as Python sees them, and the functions that add each group of bindings to the module.
#pragma once
#include "raster/texture_compression.h"
#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "pipelines/kit/render_frame.h"
#include "render_report.h"
#include "scene/scene.h"

namespace ontile::python {

// A scene loaded once and rendered many times; `path` is the file as given, as the CLI's
// report names it.
struct LoadedScene {
  std::string path;
  std::shared_ptr<const Scene> scene;
  TextureCompression texture_compression = TextureCompression::None;  // how its images are stored
};

// One rendered frame: the context owns the image surface, the report is the render verb's JSON.
struct RenderResult {
  std::shared_ptr<const Scene> scene;  // keeps textures the context's surfaces may refer to
  RenderedFrame frame;
  std::string report_json;
  std::vector<double> frame_times_ms;  // the timed frames after the warm-up (frames > 0)
};

// The camera override of ontile.render(view=...): a world-to-camera matrix (row-major, as NumPy
// holds it) and optional perspective parameters; absent fields keep the selected camera's.
struct CameraOverride {
  bool has_view = false;
  glm::dmat4 view{1.0};
  std::optional<float> yfov_rad, znear, zfar;
};

void bind_render(pybind11::module_& m);
void bind_python_pipelines(pybind11::module_& m);

// Renders `settings` with `pipeline` (a registered one when null: settings.pipeline) and fills
// the report as `ontile render --report` writes it. With frames > 0, as `ontile render --frames
// N`: the first render is a warm-up, `frames` more are timed (the whole render call each, with
// frame_index 1, 2, ...), and the last one is kept.
std::unique_ptr<RenderResult> render_with(const LoadedScene& scene, const RenderSettings& settings,
                                          const CameraOverride& camera, bool tile_report, const std::string& gpu,
                                          Pipeline* pipeline, int frames = 0);

}  // namespace ontile::python
