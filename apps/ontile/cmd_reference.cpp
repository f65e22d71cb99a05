// `ontile reference`: ray-traces the lambert pipeline's image of a scene with Embree and writes
// colour plus depth, primitive-id and normal AOVs to one EXR.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "pipelines/kit/render_frame.h"
#include "reference/reference_renderer.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile::cli {
namespace {

struct ReferenceOptions {
  std::string scene, out, size = "1280x720";
  bool allow_outside_files = false, progress = false;
  int camera = -1, spp = 1;
};

void run_reference(const ReferenceOptions& o) {
  int width_px = 0, height_px = 0;
  parse_size(o.size, width_px, height_px);
  try {
    check_samples_per_pixel(o.spp);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  const std::filesystem::path out(o.out);
  if (out.extension() != ".exr") {
    throw UsageError("--out " + o.out + ": unsupported output extension '" + out.extension().string() +
                     "' (the reference writes .exr: R, G, B, A, Z, primid, N.x, N.y, N.z)");
  }
  check_output_option("--out", o.out, false);
  const Scene scene = load_scene(o.scene, o.allow_outside_files);
  const Camera camera = select_camera(scene, o.camera);
  const LambertReferenceScene ref = make_lambert_reference_scene(scene, camera, width_px, height_px);
  Progress progress("reference", o.progress);
  const ReferenceImage image = render_reference(ref, width_px, height_px, o.spp, progress.callback());
  write_reference_exr(out, image);
  std::printf("%s: %dx%d reference, %d samples per pixel, %llu triangles; wrote %s\n", o.scene.c_str(),
              width_px, height_px, o.spp, static_cast<unsigned long long>(ref.geometry->triangle_count()),
              o.out.c_str());
}

}  // namespace

void add_reference_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("reference", "Ray-trace the lambert pipeline's reference image (Embree) with AOVs");
  auto o = std::make_shared<ReferenceOptions>();
  add_scene_options(cmd, o->scene, o->allow_outside_files, "glTF scene (.gltf or .glb)");
  cmd->add_option("--out", o->out, "Output EXR (R, G, B, A, Z, primid, N.x, N.y, N.z)")->required();
  cmd->add_option("--camera", o->camera, "Camera index in the scene (default: first camera, or a framing camera)")
      ->check(CLI::Range(0, 1 << 20));
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT, each side 1..16384 (default 1280x720)");
  cmd->add_option("--spp", o->spp, "Samples per pixel: a perfect square 1, 4, 9, ... 256 (stratified grid; default 1)");
  add_progress_flag(cmd, o->progress);
  cmd->callback([o] { run_reference(*o); });
}

}  // namespace ontile::cli
