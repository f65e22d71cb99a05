// One call that renders a frame of a scene with a named pipeline: picks the camera, sets up
// the context (threads, tiles, budget) and returns the final image and traffic report.
// Used by the CLI, the tests and the benchmarks so they all render the same way.
#pragma once
#include <memory>
#include <string>

#include "pipelines/kit/pipeline.h"

namespace ontile {

struct RenderSettings {
  std::string pipeline = "lambert";
  int camera_index = -1;  // -1: the scene's first camera, or a default framing camera
  int width_px = 1280, height_px = 720;
  ContextConfig context;
  PipelineOptions options;
  // A panning camera: frame i sees the selected camera turned i x camera_pan_deg_per_frame
  // degrees about the world's vertical (+Y) axis through its position. Frames render alike
  // without it.
  int frame_index = 0;
  double camera_pan_deg_per_frame = 0.0;
};

struct RenderedFrame {
  std::unique_ptr<RenderContext> context;  // owns the surfaces
  FrameOutputs outputs;
  Camera camera;
};

// Throws ontile::Error for an unknown pipeline, a camera index out of range or a bad size.
Camera select_camera(const Scene& scene, int camera_index);
// The pipeline's inputs for `settings`: size checked, camera selected, options copied.
FrameInputs frame_inputs(const Scene& scene, const RenderSettings& settings);
RenderedFrame render_frame(const Scene& scene, const RenderSettings& settings);

}  // namespace ontile
