// measure_accuracy (see accuracy_run.h).
#include "reference/accuracy_run.h"

#include "aov/aov_pass.h"
#include "util/error.h"

namespace ontile {

AccuracyRun measure_accuracy(const Scene& scene, const RenderSettings& settings, const ProgressCallback& progress) {
  if (settings.pipeline != "lambert") {
    throw Error("accuracy: pipeline '" + settings.pipeline +
                "' has no reference renderer (only lambert is supported)");
  }
  if (progress) progress(0, 3, "rasterizing");
  const RenderedFrame frame = render_frame(scene, settings);
  const AovFrame aovs = render_aov_frame(scene, settings, {AovKind::Depth, AovKind::PrimitiveId});
  const LambertReferenceScene ref =
      make_lambert_reference_scene(scene, frame.camera, settings.width_px, settings.height_px);
  AccuracyRun run;
  if (progress) progress(1, 3, "ray-casting the reference");
  run.reference = render_reference(ref, settings.width_px, settings.height_px, 1);
  if (progress) progress(2, 3, "comparing");
  AccuracyInputs in;
  in.reference = &run.reference;
  in.geometry = ref.geometry.get();
  in.renderers = &ref.renderers.renderers;
  in.camera = ref.camera;
  in.raster_color = frame.outputs.color;
  in.raster_depth = aovs.surfaces[0];
  in.raster_primitive_id = aovs.surfaces[1];
  run.metrics = compare_with_reference(in);
  if (progress) progress(3, 3, "done");
  return run;
}

}  // namespace ontile
