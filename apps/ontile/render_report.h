// The render verb's JSON report: the frame's traffic report plus what was run (scene, pipeline,
// every option, size, ontile version), so that a report describes itself
// (docs/report.schema.json; `ontile diff` reads two of them).
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "context/frame_report.h"
#include "pipelines/kit/render_frame.h"

namespace ontile {

struct RenderRun {
  std::string scene;             // the scene file as given
  RenderSettings settings;       // pipeline, options, size, camera, context configuration
  std::string aov;               // --aov, empty when the pipeline's image was rendered
  std::optional<int> frames;     // --frames
  bool tiles = false;            // --tiles: per-tile statistics in the report
  std::string gpu;               // --gpu preset, empty without it
  TextureCompression texture_compression = TextureCompression::None;  // scene images' storage
};

nlohmann::json render_report_json(const FrameReport& report, const RenderRun& run);

}  // namespace ontile
