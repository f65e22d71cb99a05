// The deferred-shading bandwidth study (docs/deferred.md): renders one scene with the design
// variants of Khronos Vulkan-Samples' render_subpasses and msaa samples (two render passes vs
// subpasses, transient attachments off, a G-buffer over 128 bits, forward, 4x MSAA resolved on
// tile vs separately) and reports bytes per frame by category beside the published Mali-G76
// measurements.
#pragma once
#include "util/progress.h"
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "tiler/render_pass_executor.h"

namespace ontile {

struct StudyVariant {
  std::string label;
  std::string pipeline;
  std::vector<std::pair<std::string, std::string>> options;
};

struct StudySettings {
  int width_px = 2220, height_px = 1080;  // the Mali-G76 device's screen in the sample
  int tile_size_px = 16;
  int color_budget_bits_per_px = 128;
  int threads = 0;
  int lights = 48;  // the sample's Sponza lights: 8 x 2 x 3 point lights
  int frames = 1;   // frame time is the median over this many frames
  int parameter_cache_kib = 0;  // an L2 model for parameter-buffer reads (0: none)
  // A --gpu preset (tiler/gpu_presets.h) instead of the three settings above; with transaction
  // elimination each variant renders one more frame first, so its row is the steady state of a
  // static camera (every variant starts from an empty CRC history).
  std::string gpu;
  // The application's choices no preset makes: stored varying size, and the storage format of
  // the scene's textures (the caller loads the scene with it; reported here).
  VaryingPrecision varying_precision = VaryingPrecision::Fp32;
  std::string texture_compression = "none";
  ProgressCallback progress;    // optional: hears of every rendered frame
};

struct StudyRow {
  StudyVariant variant;
  uint64_t bytes_read = 0, bytes_written = 0;
  std::map<std::string, uint64_t> bytes_by_category;
  uint64_t tiles = 0;             // tiles of every pass, the PTILES counter the sample reads
  int tile_width_px = 0, tile_height_px = 0;  // of the first pass
  int passes = 0;
  double median_frame_ms = 0.0;
};

// Two render passes (the G-buffer stored and loaded back, as the sample), subpasses, subpasses
// without transient attachments, the same with the G-buffer and depth stored (store op STORE),
// subpasses with the vulkan-samples-large G-buffer, forward, forward 4x MSAA resolved on tile,
// forward 4x MSAA stored and resolved by a separate pass, and two render passes whose lighting
// samples the G-buffer as textures (deferred-classic); every variant with `lights` generated
// point lights.
std::vector<StudyVariant> deferred_study_variants(int lights);

// Renders every variant (traffic is deterministic; time is the median over settings.frames).
std::vector<StudyRow> run_study(const Scene& scene, const StudySettings& settings,
                                const std::vector<StudyVariant>& variants);

// The study as JSON for scripts (docs/deferred.md): the settings, every variant with its bytes by
// category, and `ratios` {read, write, total} of "two render passes" over "subpasses,
// transient" beside the published Mali-G76 per-frame ratios (absent when either row is).
nlohmann::json deferred_study_json(const std::vector<StudyRow>& rows, const StudySettings& settings,
                                   const std::string& scene_name);

// Markdown: the bytes table, then ours against the published Mali-G76 figures as ratios.
std::string deferred_study_markdown(const std::vector<StudyRow>& rows, const StudySettings& settings,
                                    const std::string& scene_name);

}  // namespace ontile
