// One call that measures the rasterizer against the reference for a scene and camera: renders
// lambert's image, the depth and primitive-id AOVs, and the ray-traced reference, then compares.
#pragma once
#include "pipelines/kit/render_frame.h"
#include "reference/accuracy_metrics.h"
#include "util/progress.h"

namespace ontile {

struct AccuracyRun {
  ReferenceImage reference;
  AccuracyMetrics metrics;
};

// settings.pipeline must be "lambert" (the only pipeline the reference reproduces) and
// settings.options empty; otherwise Error.
// `progress` (optional) hears of each step: the raster frame, its AOVs, the reference rows, the comparison.
AccuracyRun measure_accuracy(const Scene& scene, const RenderSettings& settings,
                             const ProgressCallback& progress = {});

}  // namespace ontile
