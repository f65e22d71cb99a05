// render_frame (see render_frame.h).
#include "pipelines/kit/render_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include "util/error.h"

namespace ontile {

Camera select_camera(const Scene& scene, int camera_index) {
  if (camera_index < 0) return scene.cameras.empty() ? default_camera(scene) : scene.cameras[0];
  if (camera_index >= static_cast<int>(scene.cameras.size())) {
    throw Error(scene.source_path + ": camera " + std::to_string(camera_index) +
                " out of range (the scene has " + std::to_string(scene.cameras.size()) + ")");
  }
  return scene.cameras[camera_index];
}

FrameInputs frame_inputs(const Scene& scene, const RenderSettings& settings) {
  if (settings.width_px <= 0 || settings.height_px <= 0 || settings.width_px > kMaxTargetSizePx ||
      settings.height_px > kMaxTargetSizePx) {
    throw Error("image size " + std::to_string(settings.width_px) + "x" +
                std::to_string(settings.height_px) + " outside 1.." + std::to_string(kMaxTargetSizePx));
  }
  FrameInputs inputs;
  inputs.scene = &scene;
  inputs.camera = select_camera(scene, settings.camera_index);
  if (settings.camera_pan_deg_per_frame != 0.0 && settings.frame_index != 0) {
    const double angle = glm::radians(settings.camera_pan_deg_per_frame * settings.frame_index);
    const glm::dvec3 position(inputs.camera.world[3]);
    inputs.camera.world = glm::translate(glm::dmat4(1.0), position) *
                          glm::rotate(glm::dmat4(1.0), angle, glm::dvec3(0.0, 1.0, 0.0)) *
                          glm::translate(glm::dmat4(1.0), -position) * inputs.camera.world;
  }
  inputs.width_px = settings.width_px;
  inputs.height_px = settings.height_px;
  inputs.options = settings.options;
  return inputs;
}

RenderedFrame render_frame(const Scene& scene, const RenderSettings& settings) {
  const FrameInputs inputs = frame_inputs(scene, settings);
  RenderedFrame frame;
  frame.camera = inputs.camera;
  std::unique_ptr<Pipeline> pipeline = make_pipeline(settings.pipeline);
  frame.context = std::make_unique<RenderContext>(settings.context);
  frame.outputs = pipeline->render(*frame.context, inputs);
  return frame;
}

}  // namespace ontile
